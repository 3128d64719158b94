using System.Globalization;

namespace Microsoft.Xna.Framework;

/// <summary>The XNA two-component vector: a mutable struct with public fields, as strategies use it.</summary>
[Serializable]
public partial struct Vector2 : IEquatable<Vector2>
{
    /// <summary>The X component.</summary>
    public float X;

    /// <summary>The Y component.</summary>
    public float Y;

    /// <summary>Creates a vector from its components.</summary>
    /// <param name="x">X.</param>
    /// <param name="y">Y.</param>
    public Vector2(float x, float y)
    {
        X = x;
        Y = y;
    }

    /// <summary>Creates a vector with both components equal.</summary>
    /// <param name="value">The value of both components.</param>
    public Vector2(float value)
        : this(value, value)
    {
    }

    /// <summary>(0, 0).</summary>
    public static Vector2 Zero => default;

    /// <summary>(1, 1).</summary>
    public static Vector2 One => new(1f, 1f);

    /// <summary>(1, 0).</summary>
    public static Vector2 UnitX => new(1f, 0f);

    /// <summary>(0, 1).</summary>
    public static Vector2 UnitY => new(0f, 1f);

    /// <summary>Euclidean length.</summary>
    /// <returns>√(X² + Y²).</returns>
    public readonly float Length() => MathF.Sqrt(LengthSquared());

    /// <summary>Squared length.</summary>
    /// <returns>X² + Y².</returns>
    public readonly float LengthSquared() => (X * X) + (Y * Y);

    /// <summary>Scales this vector to length 1 in place (NaN for a zero vector, as in XNA).</summary>
    public void Normalize()
    {
        float inverse = 1f / Length();
        X *= inverse;
        Y *= inverse;
    }

    /// <summary>The unit vector in the direction of <paramref name="value"/>.</summary>
    /// <param name="value">The vector.</param>
    /// <returns>value / |value|.</returns>
    public static Vector2 Normalize(Vector2 value)
    {
        value.Normalize();
        return value;
    }

    /// <summary>Distance between two points.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <returns>|value1 − value2|.</returns>
    public static float Distance(Vector2 value1, Vector2 value2) => (value1 - value2).Length();

    /// <summary>Squared distance between two points.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <returns>|value1 − value2|².</returns>
    public static float DistanceSquared(Vector2 value1, Vector2 value2) => (value1 - value2).LengthSquared();

    /// <summary>Dot product.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>x1·x2 + y1·y2.</returns>
    public static float Dot(Vector2 value1, Vector2 value2) => (value1.X * value2.X) + (value1.Y * value2.Y);

    /// <summary>Linear interpolation.</summary>
    /// <param name="value1">Value at 0.</param>
    /// <param name="value2">Value at 1.</param>
    /// <param name="amount">Weight of <paramref name="value2"/>.</param>
    /// <returns>value1 + (value2 − value1)·amount.</returns>
    public static Vector2 Lerp(Vector2 value1, Vector2 value2, float amount) => value1 + ((value2 - value1) * amount);

    /// <summary>Sum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 + value2.</returns>
    public static Vector2 operator +(Vector2 value1, Vector2 value2) => new(value1.X + value2.X, value1.Y + value2.Y);

    /// <summary>Difference.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 − value2.</returns>
    public static Vector2 operator -(Vector2 value1, Vector2 value2) => new(value1.X - value2.X, value1.Y - value2.Y);

    /// <summary>Opposite vector.</summary>
    /// <param name="value">The vector.</param>
    /// <returns>−value.</returns>
    public static Vector2 operator -(Vector2 value) => new(-value.X, -value.Y);

    /// <summary>Scaled vector.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>value·scaleFactor.</returns>
    public static Vector2 operator *(Vector2 value, float scaleFactor) => new(value.X * scaleFactor, value.Y * scaleFactor);

    /// <summary>Scaled vector.</summary>
    /// <param name="scaleFactor">The factor.</param>
    /// <param name="value">The vector.</param>
    /// <returns>value·scaleFactor.</returns>
    public static Vector2 operator *(float scaleFactor, Vector2 value) => value * scaleFactor;

    /// <summary>Vector divided by a number.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="divider">The divisor.</param>
    /// <returns>value / divider.</returns>
    public static Vector2 operator /(Vector2 value, float divider) => value * (1f / divider);

    /// <summary>Exact component equality.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>True when both components are equal.</returns>
    public static bool operator ==(Vector2 value1, Vector2 value2) => value1.X == value2.X && value1.Y == value2.Y;

    /// <summary>Inequality of either component.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>True when a component differs.</returns>
    public static bool operator !=(Vector2 value1, Vector2 value2) => !(value1 == value2);

    /// <summary>The same vector as a <see cref="System.Numerics.Vector2"/>.</summary>
    /// <param name="value">The vector.</param>
    public static implicit operator System.Numerics.Vector2(Vector2 value) => new(value.X, value.Y);

    /// <summary>The same vector as an XNA <see cref="Vector2"/>.</summary>
    /// <param name="value">The vector.</param>
    public static implicit operator Vector2(System.Numerics.Vector2 value) => new(value.X, value.Y);

    /// <inheritdoc/>
    public readonly bool Equals(Vector2 other) => this == other;

    /// <inheritdoc/>
    public override readonly bool Equals(object? obj) => obj is Vector2 other && Equals(other);

    /// <inheritdoc/>
    public override readonly int GetHashCode() => HashCode.Combine(X, Y);

    /// <summary>XNA's text form, <c>{X:1 Y:2}</c>.</summary>
    /// <returns>The text.</returns>
    public override readonly string ToString() => string.Create(CultureInfo.CurrentCulture, $"{{X:{X} Y:{Y}}}");
}
