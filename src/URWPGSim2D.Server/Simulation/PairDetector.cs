using System;
using System.Numerics;
using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Runs the library's exact test for one candidate pair at the bodies' current poses. A fish is
/// tested through its <see cref="FishState.RigidModel"/>: the partner is carried into the model's
/// frame (<see cref="RigidFrame"/>) and the contact carried back, so a fish that moved or turned
/// within the cycle is not rebuilt (except against a rectangle obstacle, or a goal block once the
/// fish has turned: those are tested against the fish rebuilt at its pose); two fish are tested in
/// the first one's model frame (the second one's model is rebuilt there only when their relative
/// pose changed).
/// </summary>
internal static class PairDetector
{
    /// <summary>The contact of <paramref name="pair"/> now (MTV moves A).</summary>
    public static Hit Detect(World world, in CandidatePair pair)
    {
        switch (pair.Kind)
        {
            case PairKind.FishFish:
                return DetectFishFish(world.Fish[pair.A], world.Fish[pair.B]);
            case PairKind.FishBall:
            {
                FishState fish = world.Fish[pair.A];
                FishModel model = fish.RigidModel;
                RigidFrame frame = fish.Frame;
                BallState ball = world.Balls[pair.B];
                Circle local = new(frame.ToModel(ball.Position), ball.Radius);
                return Hit.From(FishCollision.Detect(model, local)).ToWorld(frame);
            }

            case PairKind.BallBall:
            {
                Circle a = world.Balls[pair.A].Shape;
                Circle b = world.Balls[pair.B].Shape;
                return Hit.From(CollisionDetector.Detect(a, b));
            }

            case PairKind.FishStatic:
                return DetectFishStatic(world.Fish[pair.A], world.Statics[pair.B]);
            case PairKind.BallStatic:
                return DetectBallStatic(world.Balls[pair.A].Shape, world.Statics[pair.B]);
            case PairKind.FishWall:
                return FishWall.Detect(world.Field, world.Fish[pair.A]);
            default:
            {
                Circle ball = world.Balls[pair.A].Shape;
                return Hit.From(world.Field.Contain(ball));
            }
        }
    }

    // B is rebuilt at its pose in A's model frame (unless it is already there); the contact is
    // carried from A's model frame to the world.
    private static Hit DetectFishFish(FishState a, FishState b)
    {
        FishModel modelA = a.RigidModel;
        RigidFrame frameA = a.Frame;
        Vector2 position = frameA.ToModel(b.Position);
        float heading = Angles.Wrap(b.Heading - (a.Heading - modelA.Pose.Heading));
        FishPose posed = b.Model.Pose;
        if (!b.JointsCurrent || posed.Position != position || posed.Heading != heading)
        {
            b.SyncModelAt(position, heading);
        }

        return Hit.From(FishCollision.Detect(modelA, b.Model)).ToWorld(frameA);
    }

    private static Hit DetectFishStatic(FishState fish, StaticBody body)
    {
        FishModel model = fish.RigidModel;
        RigidFrame frame = fish.Frame;
        if (frame.IsIdentity)
        {
            return DetectInPlace(model, body);
        }

        switch (body.Kind)
        {
            case ShapeKind.Circle:
            {
                Circle c = new(frame.ToModel(body.Circle.Center), body.Circle.Radius);
                return Hit.From(FishCollision.Detect(model, c)).ToWorld(frame);
            }

            case ShapeKind.Aabb when frame.IsTranslation:
            {
                Vector2 shift = frame.ToModel(Vector2.Zero);
                Aabb box = new(body.Box.Min + shift, body.Box.Max + shift);
                return Hit.From(FishCollision.Detect(model, box)).ToWorld(frame);
            }

            default:
                // A turned polygon cannot be built without allocating: rebuild the fish in place instead.
                return DetectInPlace(fish.PosedModel, body);
        }
    }

    private static Hit DetectInPlace(FishModel fish, StaticBody body)
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
