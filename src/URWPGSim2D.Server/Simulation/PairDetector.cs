using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Simulation;

/// <summary>Runs the library's exact test for one candidate pair at the bodies' current poses.</summary>
internal static class PairDetector
{
    /// <summary>The contact of <paramref name="pair"/> now (MTV moves A).</summary>
    public static Hit Detect(World world, in CandidatePair pair)
    {
        switch (pair.Kind)
        {
            case PairKind.FishFish:
                return Hit.From(FishCollision.Detect(world.Fish[pair.A].PosedModel, world.Fish[pair.B].PosedModel));
            case PairKind.FishBall:
            {
                Circle ball = world.Balls[pair.B].Shape;
                return Hit.From(FishCollision.Detect(world.Fish[pair.A].PosedModel, ball));
            }

            case PairKind.BallBall:
            {
                Circle a = world.Balls[pair.A].Shape;
                Circle b = world.Balls[pair.B].Shape;
                return Hit.From(CollisionDetector.Detect(a, b));
            }

            case PairKind.FishStatic:
                return DetectFishStatic(world.Fish[pair.A].PosedModel, world.Statics[pair.B]);
            case PairKind.BallStatic:
                return DetectBallStatic(world.Balls[pair.A].Shape, world.Statics[pair.B]);
            case PairKind.FishWall:
                return Hit.From(world.Field.Contain(world.Fish[pair.A].PosedModel));
            default:
            {
                Circle ball = world.Balls[pair.A].Shape;
                return Hit.From(world.Field.Contain(ball));
            }
        }
    }

    private static Hit DetectFishStatic(FishModel fish, StaticBody body)
    {
        switch (body.Kind)
        {
            case ShapeKind.Circle:
            {
                Circle c = body.Circle;
                return Hit.From(FishCollision.Detect(fish, c));
            }

            case ShapeKind.Polygon:
            {
                ConvexPolygon p = body.Polygon;
                return Hit.From(FishCollision.Detect(fish, p));
            }

            default:
            {
                Aabb box = body.Box;
                return Hit.From(FishCollision.Detect(fish, box));
            }
        }
    }

    private static Hit DetectBallStatic(in Circle ball, StaticBody body)
    {
        switch (body.Kind)
        {
            case ShapeKind.Circle:
            {
                Circle c = body.Circle;
                return Hit.From(CollisionDetector.Detect(ball, c));
            }

            case ShapeKind.Polygon:
            {
                ConvexPolygon p = body.Polygon;
                return Hit.From(CollisionDetector.Detect(ball, p));
            }

            default:
            {
                Aabb box = body.Box;
                return Hit.From(CollisionDetector.Detect(ball, box));
            }
        }
    }
}
