using System.Numerics;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Where a body is inside the cycle: each body moves linearly in time from its last committed
/// state (position, heading, time), so it can be placed at any time of the cycle without
/// touching the others. A fish's model is only marked stale (it is rebuilt when a test needs it).
/// </summary>
internal static class Motion
{
    /// <summary>Places a fish at cycle time <paramref name="time"/>: P = P₀ + (v + noise)·Δt, θ = θ₀ + (ω + noise)·Δt.</summary>
    public static void MoveTo(FishState f, double time)
    {
        float span = (float)((time - f.BaseTime) * PhysicsConstants.CycleSeconds);
        Vector2 position = f.BasePosition + ((f.Velocity + f.NoiseVelocity) * span);
        float heading = Angles.Wrap(f.BaseHeading + ((f.AngularVelocity + f.NoiseAngularVelocity) * span));
        if (position == f.Position && heading == f.Heading)
        {
            return;
        }

        f.Position = position;
        f.Heading = heading;
        f.Invalidate();
    }

    /// <summary>Places a ball at cycle time <paramref name="time"/>: P = P₀ + (v + noise)·Δt.</summary>
    public static void MoveTo(BallState b, double time)
    {
        float span = (float)((time - b.BaseTime) * PhysicsConstants.CycleSeconds);
        b.Position = b.BasePosition + ((b.Velocity + b.NoiseVelocity) * span);
    }

    /// <summary>Commits a fish's current pose as its state at <paramref name="time"/>.</summary>
    public static void Rebase(FishState f, double time)
    {
        f.BasePosition = f.Position;
        f.BaseHeading = f.Heading;
        f.BaseTime = time;
    }

    /// <summary>Commits a ball's current position as its state at <paramref name="time"/>.</summary>
    public static void Rebase(BallState b, double time)
    {
        b.BasePosition = b.Position;
        b.BaseTime = time;
    }
}
