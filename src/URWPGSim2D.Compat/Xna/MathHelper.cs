using System;

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
}
