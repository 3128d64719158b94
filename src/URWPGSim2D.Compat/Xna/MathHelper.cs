namespace Microsoft.Xna.Framework;

/// <summary>The XNA single-precision math helpers strategies use (angles in radians).</summary>
public static class MathHelper
{
    /// <summary>π as a float.</summary>
    public const float Pi = MathF.PI;

    /// <summary>2π.</summary>
    public const float TwoPi = 2f * MathF.PI;

    /// <summary>π/2.</summary>
    public const float PiOver2 = MathF.PI / 2f;

    /// <summary>π/4.</summary>
    public const float PiOver4 = MathF.PI / 4f;

    /// <summary>Euler's number e.</summary>
    public const float E = MathF.E;

    /// <summary>log₁₀ e.</summary>
    public const float Log10E = 0.4342945f;

    /// <summary>log₂ e.</summary>
    public const float Log2E = 1.442695f;

    /// <summary>Degrees to radians.</summary>
    /// <param name="degrees">An angle in degrees.</param>
    /// <returns>degrees·π/180.</returns>
    public static float ToRadians(float degrees) => degrees * (MathF.PI / 180f);

    /// <summary>Radians to degrees.</summary>
    /// <param name="radians">An angle in radians.</param>
    /// <returns>radians·180/π.</returns>
    public static float ToDegrees(float radians) => radians * (180f / MathF.PI);

    /// <summary>The same angle in (−π, π].</summary>
    /// <param name="angle">An angle in radians.</param>
    /// <returns>angle + 2πk in (−π, π].</returns>
    public static float WrapAngle(float angle)
    {
        // Remainder by the float 2π (as XNA): ±π land on ±π exactly, then −π becomes π.
        float a = (float)Math.IEEERemainder(angle, (double)TwoPi);
        if (a <= -MathF.PI)
        {
            a += TwoPi;
        }
        else if (a > MathF.PI)
        {
            a -= TwoPi;
        }

        return a;
    }

    /// <summary>Limits a value to a range.</summary>
    /// <param name="value">The value.</param>
    /// <param name="min">Lower bound.</param>
    /// <param name="max">Upper bound.</param>
    /// <returns><paramref name="min"/> below the range, <paramref name="max"/> above it, else the value.</returns>
    public static float Clamp(float value, float min, float max)
    {
        value = value > max ? max : value;
        return value < min ? min : value;
    }

    /// <summary>Linear interpolation.</summary>
    /// <param name="value1">Value at 0.</param>
    /// <param name="value2">Value at 1.</param>
    /// <param name="amount">Weight of <paramref name="value2"/>.</param>
    /// <returns>value1 + (value2 − value1)·amount.</returns>
    public static float Lerp(float value1, float value2, float amount) => value1 + ((value2 - value1) * amount);

    /// <summary>The smaller of two values.</summary>
    /// <param name="value1">First value.</param>
    /// <param name="value2">Second value.</param>
    /// <returns>The minimum.</returns>
    public static float Min(float value1, float value2) => MathF.Min(value1, value2);

    /// <summary>The larger of two values.</summary>
    /// <param name="value1">First value.</param>
    /// <param name="value2">Second value.</param>
    /// <returns>The maximum.</returns>
    public static float Max(float value1, float value2) => MathF.Max(value1, value2);

    /// <summary>Absolute difference.</summary>
    /// <param name="value1">First value.</param>
    /// <param name="value2">Second value.</param>
    /// <returns>|value1 − value2|.</returns>
    public static float Distance(float value1, float value2) => MathF.Abs(value1 - value2);

    /// <summary>A coordinate in barycentric terms of a triangle's corner values.</summary>
    /// <param name="value1">Value at the first corner.</param>
    /// <param name="value2">Value at the second corner.</param>
    /// <param name="value3">Value at the third corner.</param>
    /// <param name="amount1">Weight of <paramref name="value2"/>.</param>
    /// <param name="amount2">Weight of <paramref name="value3"/>.</param>
    /// <returns>value1 + (value2 − value1)·amount1 + (value3 − value1)·amount2.</returns>
    public static float Barycentric(float value1, float value2, float value3, float amount1, float amount2) =>
        value1 + ((value2 - value1) * amount1) + ((value3 - value1) * amount2);

    /// <summary>Cubic ease between two values (zero slope at both ends).</summary>
    /// <param name="value1">Value at 0.</param>
    /// <param name="value2">Value at 1.</param>
    /// <param name="amount">Position, clamped to 0..1.</param>
    /// <returns>Lerp(value1, value2, 3t² − 2t³).</returns>
    public static float SmoothStep(float value1, float value2, float amount)
    {
        float t = Clamp(amount, 0f, 1f);
        return Lerp(value1, value2, t * t * (3f - (2f * t)));
    }

    /// <summary>Catmull-Rom spline through four values: the curve passes through <paramref name="value2"/> at 0 and <paramref name="value3"/> at 1.</summary>
    /// <param name="value1">The value before the segment.</param>
    /// <param name="value2">Value at 0.</param>
    /// <param name="value3">Value at 1.</param>
    /// <param name="value4">The value after the segment.</param>
    /// <param name="amount">Position on the segment (not clamped).</param>
    /// <returns>½·(2v2 + (v3 − v1)t + (2v1 − 5v2 + 4v3 − v4)t² + (3v2 − v1 − 3v3 + v4)t³).</returns>
    public static float CatmullRom(float value1, float value2, float value3, float value4, float amount)
    {
        float t2 = amount * amount;
        float t3 = t2 * amount;
        return 0.5f * ((2f * value2)
            + ((value3 - value1) * amount)
            + (((2f * value1) - (5f * value2) + (4f * value3) - value4) * t2)
            + (((3f * value2) - value1 - (3f * value3) + value4) * t3));
    }

    /// <summary>Cubic Hermite spline from a value and tangent at 0 to a value and tangent at 1.</summary>
    /// <param name="value1">Value at 0.</param>
    /// <param name="tangent1">Slope at 0.</param>
    /// <param name="value2">Value at 1.</param>
    /// <param name="tangent2">Slope at 1.</param>
    /// <param name="amount">Position (not clamped).</param>
    /// <returns>(2t³ − 3t² + 1)v1 + (3t² − 2t³)v2 + (t³ − 2t² + t)s1 + (t³ − t²)s2.</returns>
    public static float Hermite(float value1, float tangent1, float value2, float tangent2, float amount)
    {
        float t2 = amount * amount;
        float t3 = t2 * amount;
        return (((2f * t3) - (3f * t2) + 1f) * value1)
            + (((3f * t2) - (2f * t3)) * value2)
            + ((t3 - (2f * t2) + amount) * tangent1)
            + ((t3 - t2) * tangent2);
    }
}
