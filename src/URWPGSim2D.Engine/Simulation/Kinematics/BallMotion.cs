namespace URWPGSim2D.Engine.Simulation.Kinematics;

/// <summary>
/// The ball's water drag of the original: after each cycle's travel the speed drops by
/// 250 mm/s² (v ≥ 100 mm/s), 100 (50 ≤ v &lt; 100), 25 (25 ≤ v &lt; 50) or 6.25 (v &lt; 25), times
/// the cycle length, never below 0; the direction is kept.
/// </summary>
internal static class BallMotion
{
    /// <summary>Deceleration (mm/s²) at speed <paramref name="speed"/> (mm/s).</summary>
    /// <param name="speed">Current speed, mm/s.</param>
    public static float Deceleration(float speed) => speed >= 100f ? 250f : speed >= 50f ? 100f : speed >= 25f ? 25f : 6.25f;

    /// <summary>The velocity after one cycle of drag.</summary>
    /// <param name="velocity">Velocity before, mm/s.</param>
    /// <param name="dt">Cycle length, s.</param>
    public static Vector2 Decelerate(Vector2 velocity, float dt)
    {
        float speed = velocity.Length();
        if (speed <= 0f)
        {
            return Vector2.Zero;
        }

        float slower = MathF.Max(0f, speed - (Deceleration(speed) * dt));
        return velocity * (slower / speed);
    }
}
