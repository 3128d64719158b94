using System.Numerics;

namespace URWPGSim2D.Server.Simulation;

/// <summary>How fast the two bodies of a contact close along its normal (their motion in the cycle, noise included).</summary>
internal static class PairMotion
{
    /// <summary>
    /// Closing speed along the normal at the action point, mm per unit of cycle fraction:
    /// −(v_A(p) − v_B(p))·n·dt, where v(p) is a body's velocity at p (a fish's includes ω × r).
    /// Positive when the bodies approach.
    /// </summary>
    public static float ClosingRate(World world, in CandidatePair pair, in Hit hit)
    {
        Vector2 a = pair.Kind switch
        {
            PairKind.FishFish or PairKind.FishBall or PairKind.FishStatic or PairKind.FishWall => FishAt(world.Fish[pair.A], hit.Point),
            _ => BallOf(world.Balls[pair.A]),
        };
        Vector2 b = pair.Kind switch
        {
            PairKind.FishFish => FishAt(world.Fish[pair.B], hit.Point),
            PairKind.FishBall or PairKind.BallBall => BallOf(world.Balls[pair.B]),
            _ => Vector2.Zero,
        };
        return -Vector2.Dot(a - b, hit.Normal) * PhysicsConstants.CycleSeconds;
    }

    private static Vector2 FishAt(FishState f, Vector2 point) =>
        Impulse.PointVelocity(f.Velocity + f.NoiseVelocity, f.AngularVelocity + f.NoiseAngularVelocity, point - f.Position);

    private static Vector2 BallOf(BallState b) => b.Velocity + b.NoiseVelocity;
}
