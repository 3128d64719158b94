using System;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// A cheap lower bound on the distance between the two bodies of a pair now, from bounding
/// circles: a fish's body group and tail group circles carried onto it by its
/// <see cref="RigidFrame"/> (its leaves lie in their union), a ball's own circle, a static body's
/// circle or box, the pool's walls. Positive means apart by at least that much: with the pair's
/// relative travel rate r (mm per unit of cycle fraction) they cannot touch before gap / r.
/// </summary>
internal static class PairGap
{
    /// <summary>Lower bound on the gap of <paramref name="pair"/>, mm (≤ 0: they may touch).</summary>
    public static float LowerBound(World world, in CandidatePair pair)
    {
        switch (pair.Kind)
        {
            case PairKind.FishFish:
            {
                world.Fish[pair.A].Groups(out Disc a1, out Disc a2);
                world.Fish[pair.B].Groups(out Disc b1, out Disc b2);
                return MathF.Min(MathF.Min(a1.GapTo(b1), a1.GapTo(b2)), MathF.Min(a2.GapTo(b1), a2.GapTo(b2)));
            }

            case PairKind.FishBall:
            {
                world.Fish[pair.A].Groups(out Disc a1, out Disc a2);
                Disc ball = BallDisc(world.Balls[pair.B]);
                return MathF.Min(a1.GapTo(ball), a2.GapTo(ball));
            }

            case PairKind.BallBall:
                return BallDisc(world.Balls[pair.A]).GapTo(BallDisc(world.Balls[pair.B]));
            case PairKind.FishStatic:
            {
                world.Fish[pair.A].Groups(out Disc a1, out Disc a2);
                StaticBody body = world.Statics[pair.B];
                return MathF.Min(ToStatic(a1, body), ToStatic(a2, body));
            }

            case PairKind.BallStatic:
                return ToStatic(BallDisc(world.Balls[pair.A]), world.Statics[pair.B]);
            case PairKind.FishWall:
            {
                world.Fish[pair.A].Groups(out Disc a1, out Disc a2);
                var pool = world.Field.Bounds;
                return MathF.Min(a1.ClearanceInside(pool.Min, pool.Max), a2.ClearanceInside(pool.Min, pool.Max));
            }

            default:
            {
                var pool = world.Field.Bounds;
                return BallDisc(world.Balls[pair.A]).ClearanceInside(pool.Min, pool.Max);
            }
        }
    }

    private static Disc BallDisc(BallState ball) => new(ball.Position, ball.Radius);

    private static float ToStatic(in Disc disc, StaticBody body) =>
        body.Kind == URWPGSim2D.Collision.Shapes.ShapeKind.Circle
            ? disc.GapTo(new Disc(body.Circle.Center, body.Circle.Radius))
            : disc.GapTo(body.Bounds.Min, body.Bounds.Max);
}
