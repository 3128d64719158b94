using System;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.Motion;

/// <summary>Angle wrapping for headings (radians).</summary>
internal static class Angle
{
    /// <summary>Wraps an angle to [−π, π).</summary>
    public static float Wrap(float angle)
    {
        if (angle >= -MathF.PI && angle < MathF.PI)
        {
            return angle;
        }

        float a = angle - ((2f * MathF.PI) * MathF.Floor((angle + MathF.PI) / (2f * MathF.PI)));
        return a >= MathF.PI ? a - (2f * MathF.PI) : a;
    }
}
