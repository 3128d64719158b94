namespace URWPGSim2D.Collision.Motion;

/// <summary>Angle wrapping for headings (radians): the one wrap the library, the server and the built-in strategies use.</summary>
public static class Angle
{
    /// <summary>Wraps an angle to [−π, π): an angle already in range is returned unchanged (bit for bit).</summary>
    /// <param name="angle">An angle, rad.</param>
    /// <returns>The same direction as an angle in [−π, π).</returns>
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
