namespace Microsoft.Xna.Framework;

/// <summary>XNA 3.1's remaining members of <see cref="Vector2"/>: component-wise arithmetic, splines, the <c>ref</c>/<c>out</c> overloads.</summary>
public partial struct Vector2
{
    /// <summary>Component-wise product.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(x1·x2, y1·y2).</returns>
    public static Vector2 operator *(Vector2 value1, Vector2 value2) =>
        new(value1.X * value2.X, value1.Y * value2.Y);

    /// <summary>Component-wise quotient.</summary>
    /// <param name="value1">Dividend.</param>
    /// <param name="value2">Divisor.</param>
    /// <returns>(x1/x2, y1/y2).</returns>
    public static Vector2 operator /(Vector2 value1, Vector2 value2) =>
        new(value1.X / value2.X, value1.Y / value2.Y);

    /// <summary>Sum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 + value2.</returns>
    public static Vector2 Add(Vector2 value1, Vector2 value2) =>
        value1 + value2;

    /// <summary>The <c>ref</c> form of <see cref="Add(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">value1 + value2.</param>
    public static void Add(ref Vector2 value1, ref Vector2 value2, out Vector2 result) =>
        result = Add(value1, value2);

    /// <summary>Difference.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>value1 − value2.</returns>
    public static Vector2 Subtract(Vector2 value1, Vector2 value2) =>
        value1 - value2;

    /// <summary>The <c>ref</c> form of <see cref="Subtract(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">value1 − value2.</param>
    public static void Subtract(ref Vector2 value1, ref Vector2 value2, out Vector2 result) =>
        result = Subtract(value1, value2);

    /// <summary>Component-wise product.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(x1·x2, y1·y2).</returns>
    public static Vector2 Multiply(Vector2 value1, Vector2 value2) =>
        value1 * value2;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">(x1·x2, y1·y2).</param>
    public static void Multiply(ref Vector2 value1, ref Vector2 value2, out Vector2 result) =>
        result = Multiply(value1, value2);

    /// <summary>Scaled vector.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <returns>value1·scaleFactor.</returns>
    public static Vector2 Multiply(Vector2 value1, float scaleFactor) =>
        value1 * scaleFactor;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Vector2, float)"/>.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <param name="result">value1·scaleFactor.</param>
    public static void Multiply(ref Vector2 value1, float scaleFactor, out Vector2 result) =>
        result = Multiply(value1, scaleFactor);

    /// <summary>Component-wise quotient.</summary>
    /// <param name="value1">Dividend.</param>
    /// <param name="value2">Divisor.</param>
    /// <returns>(x1/x2, y1/y2).</returns>
    public static Vector2 Divide(Vector2 value1, Vector2 value2) =>
        value1 / value2;

    /// <summary>The <c>ref</c> form of <see cref="Divide(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">Dividend.</param>
    /// <param name="value2">Divisor.</param>
    /// <param name="result">(x1/x2, y1/y2).</param>
    public static void Divide(ref Vector2 value1, ref Vector2 value2, out Vector2 result) =>
        result = Divide(value1, value2);

    /// <summary>Vector divided by a number.</summary>
    /// <param name="value1">Dividend.</param>
    /// <param name="divider">Divisor.</param>
    /// <returns>value1 / divider.</returns>
    public static Vector2 Divide(Vector2 value1, float divider) =>
        value1 / divider;

    /// <summary>The <c>ref</c> form of <see cref="Divide(Vector2, float)"/>.</summary>
    /// <param name="value1">Dividend.</param>
    /// <param name="divider">Divisor.</param>
    /// <param name="result">value1 / divider.</param>
    public static void Divide(ref Vector2 value1, float divider, out Vector2 result) =>
        result = Divide(value1, divider);

    /// <summary>Opposite vector.</summary>
    /// <param name="value">The vector.</param>
    /// <returns>−value.</returns>
    public static Vector2 Negate(Vector2 value) =>
        -value;

    /// <summary>The <c>ref</c> form of <see cref="Negate(Vector2)"/>.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="result">−value.</param>
    public static void Negate(ref Vector2 value, out Vector2 result) =>
        result = Negate(value);

    /// <summary>Component-wise minimum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(min x, min y).</returns>
    public static Vector2 Min(Vector2 value1, Vector2 value2) =>
        new(value1.X < value2.X ? value1.X : value2.X, value1.Y < value2.Y ? value1.Y : value2.Y);

    /// <summary>The <c>ref</c> form of <see cref="Min(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">(min x, min y).</param>
    public static void Min(ref Vector2 value1, ref Vector2 value2, out Vector2 result) =>
        result = Min(value1, value2);

    /// <summary>Component-wise maximum.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <returns>(max x, max y).</returns>
    public static Vector2 Max(Vector2 value1, Vector2 value2) =>
        new(value1.X > value2.X ? value1.X : value2.X, value1.Y > value2.Y ? value1.Y : value2.Y);

    /// <summary>The <c>ref</c> form of <see cref="Max(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">(max x, max y).</param>
    public static void Max(ref Vector2 value1, ref Vector2 value2, out Vector2 result) =>
        result = Max(value1, value2);

    /// <summary>Component-wise clamp (the lower bound wins if the bounds cross, as in XNA).</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="min">Lower bounds.</param>
    /// <param name="max">Upper bounds.</param>
    /// <returns>Each component limited to its range.</returns>
    public static Vector2 Clamp(Vector2 value1, Vector2 min, Vector2 max) =>
        new(MathHelper.Clamp(value1.X, min.X, max.X), MathHelper.Clamp(value1.Y, min.Y, max.Y));

    /// <summary>The <c>ref</c> form of <see cref="Clamp(Vector2, Vector2, Vector2)"/>.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="min">Lower bounds.</param>
    /// <param name="max">Upper bounds.</param>
    /// <param name="result">Each component limited to its range.</param>
    public static void Clamp(ref Vector2 value1, ref Vector2 min, ref Vector2 max, out Vector2 result) =>
        result = Clamp(value1, min, max);

    /// <summary>Reflection of a direction off a surface with the given unit normal.</summary>
    /// <param name="vector">Incoming direction.</param>
    /// <param name="normal">Unit surface normal.</param>
    /// <returns>vector − 2·(vector·normal)·normal.</returns>
    public static Vector2 Reflect(Vector2 vector, Vector2 normal) =>
        vector - (normal * (2f * Dot(vector, normal)));

    /// <summary>The <c>ref</c> form of <see cref="Reflect(Vector2, Vector2)"/>.</summary>
    /// <param name="vector">Incoming direction.</param>
    /// <param name="normal">Unit surface normal.</param>
    /// <param name="result">vector − 2·(vector·normal)·normal.</param>
    public static void Reflect(ref Vector2 vector, ref Vector2 normal, out Vector2 result) =>
        result = Reflect(vector, normal);

    /// <summary>A point in barycentric terms of a triangle's corners, component by component.</summary>
    /// <param name="value1">First corner.</param>
    /// <param name="value2">Second corner.</param>
    /// <param name="value3">Third corner.</param>
    /// <param name="amount1">Weight of <paramref name="value2"/>.</param>
    /// <param name="amount2">Weight of <paramref name="value3"/>.</param>
    /// <returns>value1 + (value2 − value1)·amount1 + (value3 − value1)·amount2.</returns>
    public static Vector2 Barycentric(Vector2 value1, Vector2 value2, Vector2 value3, float amount1, float amount2) =>
        new(MathHelper.Barycentric(value1.X, value2.X, value3.X, amount1, amount2), MathHelper.Barycentric(value1.Y, value2.Y, value3.Y, amount1, amount2));

    /// <summary>The <c>ref</c> form of <see cref="Barycentric(Vector2, Vector2, Vector2, float, float)"/>.</summary>
    /// <param name="value1">First corner.</param>
    /// <param name="value2">Second corner.</param>
    /// <param name="value3">Third corner.</param>
    /// <param name="amount1">Weight of <paramref name="value2"/>.</param>
    /// <param name="amount2">Weight of <paramref name="value3"/>.</param>
    /// <param name="result">value1 + (value2 − value1)·amount1 + (value3 − value1)·amount2.</param>
    public static void Barycentric(ref Vector2 value1, ref Vector2 value2, ref Vector2 value3, float amount1, float amount2, out Vector2 result) =>
        result = Barycentric(value1, value2, value3, amount1, amount2);

    /// <summary>Catmull-Rom spline through four points, component by component (<see cref="MathHelper.CatmullRom"/>).</summary>
    /// <param name="value1">The point before the segment.</param>
    /// <param name="value2">The point at 0.</param>
    /// <param name="value3">The point at 1.</param>
    /// <param name="value4">The point after the segment.</param>
    /// <param name="amount">Position on the segment.</param>
    /// <returns>The point on the curve.</returns>
    public static Vector2 CatmullRom(Vector2 value1, Vector2 value2, Vector2 value3, Vector2 value4, float amount) =>
        new(MathHelper.CatmullRom(value1.X, value2.X, value3.X, value4.X, amount), MathHelper.CatmullRom(value1.Y, value2.Y, value3.Y, value4.Y, amount));

    /// <summary>The <c>ref</c> form of <see cref="CatmullRom(Vector2, Vector2, Vector2, Vector2, float)"/>.</summary>
    /// <param name="value1">The point before the segment.</param>
    /// <param name="value2">The point at 0.</param>
    /// <param name="value3">The point at 1.</param>
    /// <param name="value4">The point after the segment.</param>
    /// <param name="amount">Position on the segment.</param>
    /// <param name="result">The point on the curve.</param>
    public static void CatmullRom(ref Vector2 value1, ref Vector2 value2, ref Vector2 value3, ref Vector2 value4, float amount, out Vector2 result) =>
        result = CatmullRom(value1, value2, value3, value4, amount);

    /// <summary>Cubic Hermite spline, component by component (<see cref="MathHelper.Hermite"/>).</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="tangent1">The tangent at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="tangent2">The tangent at 1.</param>
    /// <param name="amount">Position.</param>
    /// <returns>The point on the curve.</returns>
    public static Vector2 Hermite(Vector2 value1, Vector2 tangent1, Vector2 value2, Vector2 tangent2, float amount) =>
        new(MathHelper.Hermite(value1.X, tangent1.X, value2.X, tangent2.X, amount), MathHelper.Hermite(value1.Y, tangent1.Y, value2.Y, tangent2.Y, amount));

    /// <summary>The <c>ref</c> form of <see cref="Hermite(Vector2, Vector2, Vector2, Vector2, float)"/>.</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="tangent1">The tangent at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="tangent2">The tangent at 1.</param>
    /// <param name="amount">Position.</param>
    /// <param name="result">The point on the curve.</param>
    public static void Hermite(ref Vector2 value1, ref Vector2 tangent1, ref Vector2 value2, ref Vector2 tangent2, float amount, out Vector2 result) =>
        result = Hermite(value1, tangent1, value2, tangent2, amount);

    /// <summary>Cubic ease between two points (<see cref="MathHelper.SmoothStep"/> on each component; the amount is clamped to 0..1).</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="amount">Position.</param>
    /// <returns>The eased point.</returns>
    public static Vector2 SmoothStep(Vector2 value1, Vector2 value2, float amount) =>
        new(MathHelper.SmoothStep(value1.X, value2.X, amount), MathHelper.SmoothStep(value1.Y, value2.Y, amount));

    /// <summary>The <c>ref</c> form of <see cref="SmoothStep(Vector2, Vector2, float)"/>.</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="amount">Position.</param>
    /// <param name="result">The eased point.</param>
    public static void SmoothStep(ref Vector2 value1, ref Vector2 value2, float amount, out Vector2 result) =>
        result = SmoothStep(value1, value2, amount);

    /// <summary>The <c>ref</c> form of <see cref="Lerp(Vector2, Vector2, float)"/>.</summary>
    /// <param name="value1">Value at 0.</param>
    /// <param name="value2">Value at 1.</param>
    /// <param name="amount">Weight of <paramref name="value2"/>.</param>
    /// <param name="result">value1 + (value2 − value1)·amount.</param>
    public static void Lerp(ref Vector2 value1, ref Vector2 value2, float amount, out Vector2 result) =>
        result = Lerp(value1, value2, amount);

    /// <summary>The <c>ref</c> form of <see cref="Distance(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <param name="result">|value1 − value2|.</param>
    public static void Distance(ref Vector2 value1, ref Vector2 value2, out float result) =>
        result = Distance(value1, value2);

    /// <summary>The <c>ref</c> form of <see cref="DistanceSquared(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First point.</param>
    /// <param name="value2">Second point.</param>
    /// <param name="result">|value1 − value2|².</param>
    public static void DistanceSquared(ref Vector2 value1, ref Vector2 value2, out float result) =>
        result = DistanceSquared(value1, value2);

    /// <summary>The <c>ref</c> form of <see cref="Dot(Vector2, Vector2)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">x1·x2 + y1·y2.</param>
    public static void Dot(ref Vector2 value1, ref Vector2 value2, out float result) =>
        result = Dot(value1, value2);

    /// <summary>The <c>ref</c> form of <see cref="Normalize(Vector2)"/>.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="result">value / |value| (NaN for a zero vector).</param>
    public static void Normalize(ref Vector2 value, out Vector2 result) =>
        result = Normalize(value);
}
