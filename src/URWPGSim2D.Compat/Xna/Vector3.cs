using System.Globalization;

namespace Microsoft.Xna.Framework;

/// <summary>
/// The XNA 3.1 three-component vector the original's strategies use: a mutable struct with public
/// fields, so <c>v.X = 3</c> and the mutating <see cref="Normalize()"/> work as they did. Positions are
/// (X, 0, Z) in mm. Converts implicitly to and from <see cref="System.Numerics.Vector3"/>.
/// </summary>
[Serializable]
public partial struct Vector3 : IEquatable<Vector3>
{
    /// <summary>The X component.</summary>
    public float X;

    /// <summary>The Y component (0 in the 2D simulator).</summary>
    public float Y;

    /// <summary>The Z component (+Z points down the screen).</summary>
    public float Z;

    /// <summary>Creates a vector from its components.</summary>
    /// <param name="x">X.</param>
    /// <param name="y">Y.</param>
    /// <param name="z">Z.</param>
    public Vector3(float x, float y, float z)
    {
        X = x;
        Y = y;
        Z = z;
    }

    /// <summary>Creates a vector with all three components equal.</summary>
    /// <param name="value">The value of every component.</param>
    public Vector3(float value)
        : this(value, value, value)
    {
    }

    /// <summary>Creates a vector from a two-component vector (X, Y) and a Z.</summary>
    /// <param name="value">X and Y.</param>
    /// <param name="z">Z.</param>
    public Vector3(Vector2 value, float z)
        : this(value.X, value.Y, z)
    {
    }

    /// <summary>(0, 0, 0).</summary>
    public static Vector3 Zero => default;

    /// <summary>(1, 1, 1).</summary>
    public static Vector3 One => new(1f, 1f, 1f);

    /// <summary>(1, 0, 0).</summary>
    public static Vector3 UnitX => new(1f, 0f, 0f);

    /// <summary>(0, 1, 0).</summary>
    public static Vector3 UnitY => new(0f, 1f, 0f);

    /// <summary>(0, 0, 1).</summary>
    public static Vector3 UnitZ => new(0f, 0f, 1f);

    /// <summary>(0, 1, 0).</summary>
    public static Vector3 Up => new(0f, 1f, 0f);

    /// <summary>(0, −1, 0).</summary>
    public static Vector3 Down => new(0f, -1f, 0f);

    /// <summary>(1, 0, 0).</summary>
    public static Vector3 Right => new(1f, 0f, 0f);

    /// <summary>(−1, 0, 0).</summary>
    public static Vector3 Left => new(-1f, 0f, 0f);

    /// <summary>(0, 0, −1), XNA's right-handed forward.</summary>
    public static Vector3 Forward => new(0f, 0f, -1f);

    /// <summary>(0, 0, 1).</summary>
    public static Vector3 Backward => new(0f, 0f, 1f);

    /// <summary>Euclidean length.</summary>
    /// <returns>√(X² + Y² + Z²).</returns>
    public readonly float Length() => MathF.Sqrt(LengthSquared());

    /// <summary>Squared length.</summary>
    /// <returns>X² + Y² + Z².</returns>
    public readonly float LengthSquared() => (X * X) + (Y * Y) + (Z * Z);

    /// <summary>
    /// Scales this vector to length 1 in place. As in XNA, a zero vector becomes (NaN, NaN, NaN):
    /// check <see cref="Length"/> first.
    /// </summary>
    public void Normalize()
    {
        float inverse = 1f / Length();
        X *= inverse;
        Y *= inverse;
        Z *= inverse;
    }

    /// <summary>The unit vector in the direction of <paramref name="value"/> (NaN for a zero vector).</summary>
    /// <param name="value">The vector.</param>
    /// <returns>value / |value|.</returns>
    public static Vector3 Normalize(Vector3 value)
    {
        value.Normalize();
        return value;
    }

    /// <summary>The unit vector in the direction of <paramref name="value"/>.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="result">value / |value|.</param>
    public static void Normalize(ref Vector3 value, out Vector3 result) => result = Normalize(value);

    /// <summary>Distance between two points.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <returns>|value1 − value2|.</returns>
    public static float Distance(Vector3 value1, Vector3 value2) => (value1 - value2).Length();

    /// <summary>Distance between two points.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <param name="result">|value1 − value2|.</param>
    public static void Distance(ref Vector3 value1, ref Vector3 value2, out float result) => result = Distance(value1, value2);

    /// <summary>Squared distance between two points.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <returns>|value1 − value2|².</returns>
    public static float DistanceSquared(Vector3 value1, Vector3 value2) => (value1 - value2).LengthSquared();

    /// <summary>Squared distance between two points.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <param name="result">|value1 − value2|².</param>
    public static void DistanceSquared(ref Vector3 value1, ref Vector3 value2, out float result) => result = DistanceSquared(value1, value2);

    /// <summary>Dot product.</summary>
    /// <param name="vector1">First vector.</param>
    /// <param name="vector2">Second vector.</param>
    /// <returns>x1·x2 + y1·y2 + z1·z2.</returns>
    public static float Dot(Vector3 vector1, Vector3 vector2) => (vector1.X * vector2.X) + (vector1.Y * vector2.Y) + (vector1.Z * vector2.Z);

    /// <summary>Dot product.</summary>
    /// <param name="vector1">First vector.</param>
    /// <param name="vector2">Second vector.</param>
    /// <param name="result">x1·x2 + y1·y2 + z1·z2.</param>
    public static void Dot(ref Vector3 vector1, ref Vector3 vector2, out float result) => result = Dot(vector1, vector2);

    /// <summary>Cross product (right-handed).</summary>
    /// <param name="vector1">First vector.</param>
    /// <param name="vector2">Second vector.</param>
    /// <returns>vector1 × vector2.</returns>
    public static Vector3 Cross(Vector3 vector1, Vector3 vector2) => new(
        (vector1.Y * vector2.Z) - (vector1.Z * vector2.Y),
        (vector1.Z * vector2.X) - (vector1.X * vector2.Z),
        (vector1.X * vector2.Y) - (vector1.Y * vector2.X));

    /// <summary>Cross product (right-handed).</summary>
    /// <param name="vector1">First vector.</param>
    /// <param name="vector2">Second vector.</param>
    /// <param name="result">vector1 × vector2.</param>
    public static void Cross(ref Vector3 vector1, ref Vector3 vector2, out Vector3 result) => result = Cross(vector1, vector2);

    /// <summary>Linear interpolation.</summary>
    /// <param name="value1">Value at 0.</param>
    /// <param name="value2">Value at 1.</param>
    /// <param name="amount">Weight of <paramref name="value2"/>.</param>
    /// <returns>value1 + (value2 − value1)·amount.</returns>
    public static Vector3 Lerp(Vector3 value1, Vector3 value2, float amount) => value1 + ((value2 - value1) * amount);

    /// <summary>Component-wise minimum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(min x, min y, min z).</returns>
    public static Vector3 Min(Vector3 value1, Vector3 value2) =>
        new(MathF.Min(value1.X, value2.X), MathF.Min(value1.Y, value2.Y), MathF.Min(value1.Z, value2.Z));

    /// <summary>Component-wise maximum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(max x, max y, max z).</returns>
    public static Vector3 Max(Vector3 value1, Vector3 value2) =>
        new(MathF.Max(value1.X, value2.X), MathF.Max(value1.Y, value2.Y), MathF.Max(value1.Z, value2.Z));

    /// <summary>Component-wise clamp.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="min">Lower bounds.</param>
    /// <param name="max">Upper bounds.</param>
    /// <returns>Each component limited to its range, as <see cref="MathHelper.Clamp"/> (the lower bound wins if the bounds cross, as in XNA).</returns>
    public static Vector3 Clamp(Vector3 value1, Vector3 min, Vector3 max) =>
        new(MathHelper.Clamp(value1.X, min.X, max.X), MathHelper.Clamp(value1.Y, min.Y, max.Y), MathHelper.Clamp(value1.Z, min.Z, max.Z));

    /// <summary>Reflection of a direction off a surface with the given unit normal.</summary>
    /// <param name="vector">Incoming direction.</param>
    /// <param name="normal">Unit surface normal.</param>
    /// <returns>vector − 2·(vector·normal)·normal.</returns>
    public static Vector3 Reflect(Vector3 vector, Vector3 normal) => vector - (normal * (2f * Dot(vector, normal)));

    /// <summary>Sum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 + value2.</returns>
    public static Vector3 Add(Vector3 value1, Vector3 value2) => value1 + value2;

    /// <summary>Difference.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 − value2.</returns>
    public static Vector3 Subtract(Vector3 value1, Vector3 value2) => value1 - value2;

    /// <summary>Scaled vector.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>value1·scaleFactor.</returns>
    public static Vector3 Multiply(Vector3 value1, float scaleFactor) => value1 * scaleFactor;

    /// <summary>Component-wise product.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(x1·x2, y1·y2, z1·z2).</returns>
    public static Vector3 Multiply(Vector3 value1, Vector3 value2) => value1 * value2;

    /// <summary>Vector divided by a number.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="divider">The divisor.</param>
    /// <returns>value1 / divider.</returns>
    public static Vector3 Divide(Vector3 value1, float divider) => value1 / divider;

    /// <summary>Component-wise quotient.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(x1/x2, y1/y2, z1/z2).</returns>
    public static Vector3 Divide(Vector3 value1, Vector3 value2) => value1 / value2;

    /// <summary>Opposite vector.</summary>
    /// <param name="value">The vector.</param>
    /// <returns>−value.</returns>
    public static Vector3 Negate(Vector3 value) => -value;

    /// <summary>Sum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 + value2.</returns>
    public static Vector3 operator +(Vector3 value1, Vector3 value2) => new(value1.X + value2.X, value1.Y + value2.Y, value1.Z + value2.Z);

    /// <summary>Difference.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 − value2.</returns>
    public static Vector3 operator -(Vector3 value1, Vector3 value2) => new(value1.X - value2.X, value1.Y - value2.Y, value1.Z - value2.Z);

    /// <summary>Opposite vector.</summary>
    /// <param name="value">The vector.</param>
    /// <returns>−value.</returns>
    public static Vector3 operator -(Vector3 value) => new(-value.X, -value.Y, -value.Z);

    /// <summary>Component-wise product.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(x1·x2, y1·y2, z1·z2).</returns>
    public static Vector3 operator *(Vector3 value1, Vector3 value2) => new(value1.X * value2.X, value1.Y * value2.Y, value1.Z * value2.Z);

    /// <summary>Scaled vector.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>value·scaleFactor.</returns>
    public static Vector3 operator *(Vector3 value, float scaleFactor) => new(value.X * scaleFactor, value.Y * scaleFactor, value.Z * scaleFactor);

    /// <summary>Scaled vector.</summary>
    /// <param name="scaleFactor">The factor.</param>
    /// <param name="value">The vector.</param>
    /// <returns>value·scaleFactor.</returns>
    public static Vector3 operator *(float scaleFactor, Vector3 value) => value * scaleFactor;

    /// <summary>Component-wise quotient.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(x1/x2, y1/y2, z1/z2).</returns>
    public static Vector3 operator /(Vector3 value1, Vector3 value2) => new(value1.X / value2.X, value1.Y / value2.Y, value1.Z / value2.Z);

    /// <summary>Vector divided by a number.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="divider">The divisor.</param>
    /// <returns>value / divider.</returns>
    public static Vector3 operator /(Vector3 value, float divider)
    {
        float inverse = 1f / divider;
        return new(value.X * inverse, value.Y * inverse, value.Z * inverse);
    }

    /// <summary>Exact component equality.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>True when all components are equal.</returns>
    public static bool operator ==(Vector3 value1, Vector3 value2) => value1.X == value2.X && value1.Y == value2.Y && value1.Z == value2.Z;

    /// <summary>Inequality of any component.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>True when a component differs.</returns>
    public static bool operator !=(Vector3 value1, Vector3 value2) => !(value1 == value2);

    /// <summary>The same vector as a <see cref="System.Numerics.Vector3"/>.</summary>
    /// <param name="value">The vector.</param>
    public static implicit operator System.Numerics.Vector3(Vector3 value) => new(value.X, value.Y, value.Z);

    /// <summary>The same vector as an XNA <see cref="Vector3"/>.</summary>
    /// <param name="value">The vector.</param>
    public static implicit operator Vector3(System.Numerics.Vector3 value) => new(value.X, value.Y, value.Z);

    /// <summary>The field-plane point (X, Z) as a <see cref="System.Numerics.Vector2"/> (Y is dropped).</summary>
    /// <returns>(X, Z).</returns>
    public readonly System.Numerics.Vector2 ToXZ() => new(X, Z);

    /// <summary>The field-plane point (x, 0, z) of a <see cref="System.Numerics.Vector2"/> (x, z).</summary>
    /// <param name="xz">X and Z.</param>
    /// <returns>(xz.X, 0, xz.Y).</returns>
    public static Vector3 FromXZ(System.Numerics.Vector2 xz) => new(xz.X, 0f, xz.Y);

    /// <summary>The same vector as a <see cref="System.Numerics.Vector3"/>.</summary>
    /// <returns>(X, Y, Z).</returns>
    public readonly System.Numerics.Vector3 ToNumerics() => this;

    /// <inheritdoc/>
    public readonly bool Equals(Vector3 other) => this == other;

    /// <inheritdoc/>
    public override readonly bool Equals(object? obj) => obj is Vector3 other && Equals(other);

    /// <inheritdoc/>
    public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z);

    /// <summary>XNA's text form, <c>{X:1 Y:2 Z:3}</c>.</summary>
    /// <returns>The text.</returns>
    public override readonly string ToString() =>
        string.Create(CultureInfo.CurrentCulture, $"{{X:{X} Y:{Y} Z:{Z}}}");
}
