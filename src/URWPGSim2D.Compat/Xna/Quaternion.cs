using System.Globalization;
using N = System.Numerics;

namespace Microsoft.Xna.Framework;

/// <summary>
/// XNA 3.1's quaternion: a mutable struct with public fields X, Y, Z (the vector part) and W (the scalar part), with
/// the conventions of <see cref="System.Numerics.Quaternion"/> (the two convert implicitly): q1·q2 applies q2 first,
/// then q1; <see cref="Concatenate(Quaternion, Quaternion)"/> applies its first argument first.
/// </summary>
[Serializable]
public struct Quaternion : IEquatable<Quaternion>
{
    /// <summary>The X component of the vector part.</summary>
    public float X;

    /// <summary>The Y component of the vector part.</summary>
    public float Y;

    /// <summary>The Z component of the vector part.</summary>
    public float Z;

    /// <summary>The scalar part.</summary>
    public float W;

    /// <summary>Creates a quaternion from its components.</summary>
    /// <param name="x">X.</param>
    /// <param name="y">Y.</param>
    /// <param name="z">Z.</param>
    /// <param name="w">W.</param>
    public Quaternion(float x, float y, float z, float w)
    {
        X = x;
        Y = y;
        Z = z;
        W = w;
    }

    /// <summary>Creates a quaternion from a vector part and a scalar part.</summary>
    /// <param name="vectorPart">X, Y, Z.</param>
    /// <param name="scalarPart">W.</param>
    public Quaternion(Vector3 vectorPart, float scalarPart)
        : this(vectorPart.X, vectorPart.Y, vectorPart.Z, scalarPart)
    {
    }

    /// <summary>(0, 0, 0, 1), no rotation.</summary>
    public static Quaternion Identity => new(0f, 0f, 0f, 1f);

    /// <summary>The same quaternion as a <see cref="System.Numerics.Quaternion"/>.</summary>
    /// <param name="value">The quaternion.</param>
    public static implicit operator N.Quaternion(Quaternion value) => new(value.X, value.Y, value.Z, value.W);

    /// <summary>The same quaternion as an XNA <see cref="Quaternion"/>.</summary>
    /// <param name="value">The quaternion.</param>
    public static implicit operator Quaternion(N.Quaternion value) => new(value.X, value.Y, value.Z, value.W);

    /// <summary>Length.</summary>
    /// <returns>√(X² + Y² + Z² + W²).</returns>
    public readonly float Length() => MathF.Sqrt(LengthSquared());

    /// <summary>Squared length.</summary>
    /// <returns>X² + Y² + Z² + W².</returns>
    public readonly float LengthSquared() => (X * X) + (Y * Y) + (Z * Z) + (W * W);

    /// <summary>Scales this quaternion to length 1 in place (NaN for zero, as XNA).</summary>
    public void Normalize()
    {
        float inverse = 1f / Length();
        X *= inverse;
        Y *= inverse;
        Z *= inverse;
        W *= inverse;
    }

    /// <summary>Negates the vector part in place (the inverse rotation of a unit quaternion).</summary>
    public void Conjugate()
    {
        X = -X;
        Y = -Y;
        Z = -Z;
    }

    /// <summary>The quaternion scaled to length 1.</summary>
    /// <param name="quaternion">The quaternion.</param>
    /// <returns>quaternion / |quaternion|.</returns>
    public static Quaternion Normalize(Quaternion quaternion) =>
        Scale(quaternion, 1f / quaternion.Length());

    /// <summary>The <c>ref</c> form of <see cref="Normalize(Quaternion)"/>.</summary>
    /// <param name="quaternion">The quaternion.</param>
    /// <param name="result">quaternion / |quaternion|.</param>
    public static void Normalize(ref Quaternion quaternion, out Quaternion result) => result = Normalize(quaternion);

    /// <summary>The conjugate: the vector part negated.</summary>
    /// <param name="value">The quaternion.</param>
    /// <returns>(−x, −y, −z, w).</returns>
    public static Quaternion Conjugate(Quaternion value) =>
        new(-value.X, -value.Y, -value.Z, value.W);

    /// <summary>The <c>ref</c> form of <see cref="Conjugate(Quaternion)"/>.</summary>
    /// <param name="value">The quaternion.</param>
    /// <param name="result">(−x, −y, −z, w).</param>
    public static void Conjugate(ref Quaternion value, out Quaternion result) => result = Conjugate(value);

    /// <summary>The multiplicative inverse.</summary>
    /// <param name="quaternion">The quaternion.</param>
    /// <returns>conjugate / |q|².</returns>
    public static Quaternion Inverse(Quaternion quaternion) =>
        Scale(Conjugate(quaternion), 1f / quaternion.LengthSquared());

    /// <summary>The <c>ref</c> form of <see cref="Inverse(Quaternion)"/>.</summary>
    /// <param name="quaternion">The quaternion.</param>
    /// <param name="result">conjugate / |q|².</param>
    public static void Inverse(ref Quaternion quaternion, out Quaternion result) => result = Inverse(quaternion);

    /// <summary>The rotation by an angle about a unit axis.</summary>
    /// <param name="axis">Unit axis.</param>
    /// <param name="angle">Angle, rad.</param>
    /// <returns>(axis·sin(angle/2), cos(angle/2)).</returns>
    public static Quaternion CreateFromAxisAngle(Vector3 axis, float angle) =>
        new(axis * MathF.Sin(angle * 0.5f), MathF.Cos(angle * 0.5f));

    /// <summary>The <c>ref</c> form of <see cref="CreateFromAxisAngle(Vector3, float)"/>.</summary>
    /// <param name="axis">Unit axis.</param>
    /// <param name="angle">Angle, rad.</param>
    /// <param name="result">(axis·sin(angle/2), cos(angle/2)).</param>
    public static void CreateFromAxisAngle(ref Vector3 axis, float angle, out Quaternion result) => result = CreateFromAxisAngle(axis, angle);

    /// <summary>The rotation by roll about Z, then pitch about X, then yaw about Y.</summary>
    /// <param name="yaw">Rotation about Y, rad.</param>
    /// <param name="pitch">Rotation about X, rad.</param>
    /// <param name="roll">Rotation about Z, rad.</param>
    /// <returns>The quaternion.</returns>
    public static Quaternion CreateFromYawPitchRoll(float yaw, float pitch, float roll) =>
        N.Quaternion.CreateFromYawPitchRoll(yaw, pitch, roll);

    /// <summary>The <c>ref</c> form of <see cref="CreateFromYawPitchRoll(float, float, float)"/>.</summary>
    /// <param name="yaw">Rotation about Y, rad.</param>
    /// <param name="pitch">Rotation about X, rad.</param>
    /// <param name="roll">Rotation about Z, rad.</param>
    /// <param name="result">The quaternion.</param>
    public static void CreateFromYawPitchRoll(float yaw, float pitch, float roll, out Quaternion result) => result = CreateFromYawPitchRoll(yaw, pitch, roll);

    /// <summary>The rotation of a pure rotation matrix.</summary>
    /// <param name="matrix">A rotation matrix.</param>
    /// <returns>The unit quaternion.</returns>
    public static Quaternion CreateFromRotationMatrix(Matrix matrix) =>
        N.Quaternion.CreateFromRotationMatrix(matrix);

    /// <summary>The <c>ref</c> form of <see cref="CreateFromRotationMatrix(Matrix)"/>.</summary>
    /// <param name="matrix">A rotation matrix.</param>
    /// <param name="result">The unit quaternion.</param>
    public static void CreateFromRotationMatrix(ref Matrix matrix, out Quaternion result) => result = CreateFromRotationMatrix(matrix);

    /// <summary>Four-component dot product.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>x1·x2 + y1·y2 + z1·z2 + w1·w2.</returns>
    public static float Dot(Quaternion quaternion1, Quaternion quaternion2) =>
        (quaternion1.X * quaternion2.X) + (quaternion1.Y * quaternion2.Y) + (quaternion1.Z * quaternion2.Z) + (quaternion1.W * quaternion2.W);

    /// <summary>The <c>ref</c> form of <see cref="Dot(Quaternion, Quaternion)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="result">x1·x2 + y1·y2 + z1·z2 + w1·w2.</param>
    public static void Dot(ref Quaternion quaternion1, ref Quaternion quaternion2, out float result) => result = Dot(quaternion1, quaternion2);

    /// <summary>Spherical interpolation along the shorter arc.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="amount">Position between the two (0..1).</param>
    /// <returns>The interpolated unit quaternion.</returns>
    public static Quaternion Slerp(Quaternion quaternion1, Quaternion quaternion2, float amount) =>
        N.Quaternion.Slerp(quaternion1, quaternion2, amount);

    /// <summary>The <c>ref</c> form of <see cref="Slerp(Quaternion, Quaternion, float)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="amount">Position between the two (0..1).</param>
    /// <param name="result">The interpolated unit quaternion.</param>
    public static void Slerp(ref Quaternion quaternion1, ref Quaternion quaternion2, float amount, out Quaternion result) => result = Slerp(quaternion1, quaternion2, amount);

    /// <summary>Linear interpolation along the shorter arc, normalized.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="amount">Position between the two (0..1).</param>
    /// <returns>The interpolated unit quaternion.</returns>
    public static Quaternion Lerp(Quaternion quaternion1, Quaternion quaternion2, float amount) =>
        N.Quaternion.Lerp(quaternion1, quaternion2, amount);

    /// <summary>The <c>ref</c> form of <see cref="Lerp(Quaternion, Quaternion, float)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="amount">Position between the two (0..1).</param>
    /// <param name="result">The interpolated unit quaternion.</param>
    public static void Lerp(ref Quaternion quaternion1, ref Quaternion quaternion2, float amount, out Quaternion result) => result = Lerp(quaternion1, quaternion2, amount);

    /// <summary>The rotation <paramref name="value1"/> followed by <paramref name="value2"/>.</summary>
    /// <param name="value1">First quaternion.</param>
    /// <param name="value2">Second quaternion.</param>
    /// <returns>value2·value1.</returns>
    public static Quaternion Concatenate(Quaternion value1, Quaternion value2) =>
        value2 * value1;

    /// <summary>The <c>ref</c> form of <see cref="Concatenate(Quaternion, Quaternion)"/>.</summary>
    /// <param name="value1">First quaternion.</param>
    /// <param name="value2">Second quaternion.</param>
    /// <param name="result">value2·value1.</param>
    public static void Concatenate(ref Quaternion value1, ref Quaternion value2, out Quaternion result) => result = Concatenate(value1, value2);

    /// <summary>Every component negated.</summary>
    /// <param name="quaternion">The quaternion.</param>
    /// <returns>−quaternion.</returns>
    public static Quaternion Negate(Quaternion quaternion) =>
        -quaternion;

    /// <summary>The <c>ref</c> form of <see cref="Negate(Quaternion)"/>.</summary>
    /// <param name="quaternion">The quaternion.</param>
    /// <param name="result">−quaternion.</param>
    public static void Negate(ref Quaternion quaternion, out Quaternion result) => result = Negate(quaternion);

    /// <summary>Component sum.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1 + quaternion2.</returns>
    public static Quaternion Add(Quaternion quaternion1, Quaternion quaternion2) =>
        quaternion1 + quaternion2;

    /// <summary>The <c>ref</c> form of <see cref="Add(Quaternion, Quaternion)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="result">quaternion1 + quaternion2.</param>
    public static void Add(ref Quaternion quaternion1, ref Quaternion quaternion2, out Quaternion result) => result = Add(quaternion1, quaternion2);

    /// <summary>Component difference.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1 − quaternion2.</returns>
    public static Quaternion Subtract(Quaternion quaternion1, Quaternion quaternion2) =>
        quaternion1 - quaternion2;

    /// <summary>The <c>ref</c> form of <see cref="Subtract(Quaternion, Quaternion)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="result">quaternion1 − quaternion2.</param>
    public static void Subtract(ref Quaternion quaternion1, ref Quaternion quaternion2, out Quaternion result) => result = Subtract(quaternion1, quaternion2);

    /// <summary>Hamilton product: the rotation <paramref name="quaternion2"/> followed by <paramref name="quaternion1"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1·quaternion2.</returns>
    public static Quaternion Multiply(Quaternion quaternion1, Quaternion quaternion2) =>
        quaternion1 * quaternion2;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Quaternion, Quaternion)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="result">quaternion1·quaternion2.</param>
    public static void Multiply(ref Quaternion quaternion1, ref Quaternion quaternion2, out Quaternion result) => result = Multiply(quaternion1, quaternion2);

    /// <summary>Every component scaled.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>quaternion1·scaleFactor.</returns>
    public static Quaternion Multiply(Quaternion quaternion1, float scaleFactor) =>
        quaternion1 * scaleFactor;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Quaternion, float)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <param name="result">quaternion1·scaleFactor.</param>
    public static void Multiply(ref Quaternion quaternion1, float scaleFactor, out Quaternion result) => result = Multiply(quaternion1, scaleFactor);

    /// <summary>Product with the inverse.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1·quaternion2⁻¹.</returns>
    public static Quaternion Divide(Quaternion quaternion1, Quaternion quaternion2) =>
        quaternion1 / quaternion2;

    /// <summary>The <c>ref</c> form of <see cref="Divide(Quaternion, Quaternion)"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <param name="result">quaternion1·quaternion2⁻¹.</param>
    public static void Divide(ref Quaternion quaternion1, ref Quaternion quaternion2, out Quaternion result) => result = Divide(quaternion1, quaternion2);

    /// <summary>Component sum.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1 + quaternion2.</returns>
    public static Quaternion operator +(Quaternion quaternion1, Quaternion quaternion2) =>
        new(quaternion1.X + quaternion2.X, quaternion1.Y + quaternion2.Y, quaternion1.Z + quaternion2.Z, quaternion1.W + quaternion2.W);

    /// <summary>Component difference.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1 − quaternion2.</returns>
    public static Quaternion operator -(Quaternion quaternion1, Quaternion quaternion2) =>
        new(quaternion1.X - quaternion2.X, quaternion1.Y - quaternion2.Y, quaternion1.Z - quaternion2.Z, quaternion1.W - quaternion2.W);

    /// <summary>Every component negated.</summary>
    /// <param name="quaternion">The quaternion.</param>
    /// <returns>−quaternion.</returns>
    public static Quaternion operator -(Quaternion quaternion) => new(-quaternion.X, -quaternion.Y, -quaternion.Z, -quaternion.W);

    /// <summary>Hamilton product: the rotation <paramref name="quaternion2"/> followed by <paramref name="quaternion1"/>.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1·quaternion2.</returns>
    public static Quaternion operator *(Quaternion quaternion1, Quaternion quaternion2)
    {
        var (a, b) = (quaternion1, quaternion2);
        return new(
            (a.W * b.X) + (a.X * b.W) + (a.Y * b.Z) - (a.Z * b.Y),
            (a.W * b.Y) - (a.X * b.Z) + (a.Y * b.W) + (a.Z * b.X),
            (a.W * b.Z) + (a.X * b.Y) - (a.Y * b.X) + (a.Z * b.W),
            (a.W * b.W) - (a.X * b.X) - (a.Y * b.Y) - (a.Z * b.Z));
    }

    /// <summary>Every component scaled.</summary>
    /// <param name="quaternion1">The quaternion.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>quaternion1·scaleFactor.</returns>
    public static Quaternion operator *(Quaternion quaternion1, float scaleFactor) => Scale(quaternion1, scaleFactor);

    /// <summary>Product with the inverse.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>quaternion1·quaternion2⁻¹.</returns>
    public static Quaternion operator /(Quaternion quaternion1, Quaternion quaternion2) => quaternion1 * Inverse(quaternion2);

    /// <summary>Exact component equality.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>True when all components are equal.</returns>
    public static bool operator ==(Quaternion quaternion1, Quaternion quaternion2) => quaternion1.Equals(quaternion2);

    /// <summary>Inequality of any component.</summary>
    /// <param name="quaternion1">First quaternion.</param>
    /// <param name="quaternion2">Second quaternion.</param>
    /// <returns>True when a component differs.</returns>
    public static bool operator !=(Quaternion quaternion1, Quaternion quaternion2) => !quaternion1.Equals(quaternion2);

    /// <inheritdoc/>
    public readonly bool Equals(Quaternion other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;

    /// <inheritdoc/>
    public override readonly bool Equals(object? obj) => obj is Quaternion other && Equals(other);

    /// <inheritdoc/>
    public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);

    /// <summary>XNA's text form, <c>{X:0 Y:0 Z:0 W:1}</c>.</summary>
    /// <returns>The text.</returns>
    public override readonly string ToString() => string.Create(CultureInfo.CurrentCulture, $"{{X:{X} Y:{Y} Z:{Z} W:{W}}}");

    private static Quaternion Scale(Quaternion q, float f) => new(q.X * f, q.Y * f, q.Z * f, q.W * f);
}
