namespace URWPGSim2D.Server.Json;

/// <summary>Numbers and points as the output writes them: single precision, negative zero written as 0.</summary>
internal static class OutputNumbers
{
    /// <summary>The value, with −0 mapped to +0 (−0 == 0, so every other value is unchanged).</summary>
    /// <param name="value">A finite value.</param>
    /// <returns>The value to write.</returns>
    public static float Clean(float value) => value == 0f ? 0f : value;

    /// <summary>A plane point as <c>[x, z]</c> (X = world X, Y = world Z), mm.</summary>
    /// <param name="point">The point.</param>
    /// <returns>A two-element array.</returns>
    public static float[] Point(Vector2 point) => [Clean(point.X), Clean(point.Y)];

    /// <summary>Points as <c>[[x, z], ...]</c>, in the given order.</summary>
    /// <param name="points">The points.</param>
    /// <returns>An array of two-element arrays.</returns>
    public static float[][] Points(ReadOnlySpan<Vector2> points)
    {
        var result = new float[points.Length][];
        for (int i = 0; i < points.Length; i++)
        {
            result[i] = Point(points[i]);
        }

        return result;
    }
}
