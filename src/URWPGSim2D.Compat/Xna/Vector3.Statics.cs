namespace Microsoft.Xna.Framework;

/// <summary>XNA 3.1's remaining static members of <see cref="Vector3"/>: the splines and the <c>ref</c>/<c>out</c> overloads.</summary>
public partial struct Vector3
{
    /// <summary>A point in barycentric terms of a triangle's corners, component by component (<see cref="MathHelper.Barycentric"/>).</summary>
    /// <param name="value1">First corner.</param>
    /// <param name="value2">Second corner.</param>
    /// <param name="value3">Third corner.</param>
    /// <param name="amount1">Weight of <paramref name="value2"/>.</param>
    /// <param name="amount2">Weight of <paramref name="value3"/>.</param>
    /// <returns>value1 + (value2 − value1)·amount1 + (value3 − value1)·amount2.</returns>
    public static Vector3 Barycentric(Vector3 value1, Vector3 value2, Vector3 value3, float amount1, float amount2) => new(
        MathHelper.Barycentric(value1.X, value2.X, value3.X, amount1, amount2),
        MathHelper.Barycentric(value1.Y, value2.Y, value3.Y, amount1, amount2),
        MathHelper.Barycentric(value1.Z, value2.Z, value3.Z, amount1, amount2));

    /// <summary>The <c>ref</c> form of <see cref="Barycentric(Vector3, Vector3, Vector3, float, float)"/>.</summary>
    /// <param name="value1">First corner.</param>
    /// <param name="value2">Second corner.</param>
    /// <param name="value3">Third corner.</param>
    /// <param name="amount1">Weight of <paramref name="value2"/>.</param>
    /// <param name="amount2">Weight of <paramref name="value3"/>.</param>
    /// <param name="result">The point.</param>
    public static void Barycentric(ref Vector3 value1, ref Vector3 value2, ref Vector3 value3, float amount1, float amount2, out Vector3 result) =>
        result = Barycentric(value1, value2, value3, amount1, amount2);

    /// <summary>Catmull-Rom spline through four points, component by component (<see cref="MathHelper.CatmullRom"/>).</summary>
    /// <param name="value1">The point before the segment.</param>
    /// <param name="value2">The point at 0.</param>
    /// <param name="value3">The point at 1.</param>
    /// <param name="value4">The point after the segment.</param>
    /// <param name="amount">Position on the segment.</param>
    /// <returns>The point on the curve.</returns>
    public static Vector3 CatmullRom(Vector3 value1, Vector3 value2, Vector3 value3, Vector3 value4, float amount) =>
        Spline(value1, value2, value3, value4, amount, MathHelper.CatmullRom);

    /// <summary>The <c>ref</c> form of <see cref="CatmullRom(Vector3, Vector3, Vector3, Vector3, float)"/>.</summary>
    /// <param name="value1">The point before the segment.</param>
    /// <param name="value2">The point at 0.</param>
    /// <param name="value3">The point at 1.</param>
    /// <param name="value4">The point after the segment.</param>
    /// <param name="amount">Position on the segment.</param>
    /// <param name="result">The point on the curve.</param>
    public static void CatmullRom(ref Vector3 value1, ref Vector3 value2, ref Vector3 value3, ref Vector3 value4, float amount, out Vector3 result) =>
        result = CatmullRom(value1, value2, value3, value4, amount);

    /// <summary>Cubic Hermite spline, component by component (<see cref="MathHelper.Hermite"/>).</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="tangent1">The tangent at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="tangent2">The tangent at 1.</param>
    /// <param name="amount">Position.</param>
    /// <returns>The point on the curve.</returns>
    public static Vector3 Hermite(Vector3 value1, Vector3 tangent1, Vector3 value2, Vector3 tangent2, float amount) =>
        Spline(value1, tangent1, value2, tangent2, amount, MathHelper.Hermite);

    /// <summary>The <c>ref</c> form of <see cref="Hermite(Vector3, Vector3, Vector3, Vector3, float)"/>.</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="tangent1">The tangent at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="tangent2">The tangent at 1.</param>
    /// <param name="amount">Position.</param>
    /// <param name="result">The point on the curve.</param>
    public static void Hermite(ref Vector3 value1, ref Vector3 tangent1, ref Vector3 value2, ref Vector3 tangent2, float amount, out Vector3 result) =>
        result = Hermite(value1, tangent1, value2, tangent2, amount);

    /// <summary>Cubic ease between two points (<see cref="MathHelper.SmoothStep"/> on each component; the amount is clamped to 0..1).</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="amount">Position.</param>
    /// <returns>The eased point.</returns>
    public static Vector3 SmoothStep(Vector3 value1, Vector3 value2, float amount) => new(
        MathHelper.SmoothStep(value1.X, value2.X, amount),
        MathHelper.SmoothStep(value1.Y, value2.Y, amount),
        MathHelper.SmoothStep(value1.Z, value2.Z, amount));

    /// <summary>The <c>ref</c> form of <see cref="SmoothStep(Vector3, Vector3, float)"/>.</summary>
    /// <param name="value1">The point at 0.</param>
    /// <param name="value2">The point at 1.</param>
    /// <param name="amount">Position.</param>
    /// <param name="result">The eased point.</param>
    public static void SmoothStep(ref Vector3 value1, ref Vector3 value2, float amount, out Vector3 result) =>
        result = SmoothStep(value1, value2, amount);

    /// <summary>The <c>ref</c> form of <see cref="Lerp(Vector3, Vector3, float)"/>.</summary>
    /// <param name="value1">Value at 0.</param>
    /// <param name="value2">Value at 1.</param>
    /// <param name="amount">Weight of <paramref name="value2"/>.</param>
    /// <param name="result">value1 + (value2 − value1)·amount.</param>
    public static void Lerp(ref Vector3 value1, ref Vector3 value2, float amount, out Vector3 result) => result = Lerp(value1, value2, amount);

    /// <summary>The <c>ref</c> form of <see cref="Min(Vector3, Vector3)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">The component-wise minimum.</param>
    public static void Min(ref Vector3 value1, ref Vector3 value2, out Vector3 result) => result = Min(value1, value2);

    /// <summary>The <c>ref</c> form of <see cref="Max(Vector3, Vector3)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">The component-wise maximum.</param>
    public static void Max(ref Vector3 value1, ref Vector3 value2, out Vector3 result) => result = Max(value1, value2);

    /// <summary>The <c>ref</c> form of <see cref="Clamp(Vector3, Vector3, Vector3)"/>.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="min">Lower bounds.</param>
    /// <param name="max">Upper bounds.</param>
    /// <param name="result">Each component limited to its range.</param>
    public static void Clamp(ref Vector3 value1, ref Vector3 min, ref Vector3 max, out Vector3 result) => result = Clamp(value1, min, max);

    /// <summary>The <c>ref</c> form of <see cref="Reflect(Vector3, Vector3)"/>.</summary>
    /// <param name="vector">Incoming direction.</param>
    /// <param name="normal">Unit surface normal.</param>
    /// <param name="result">vector − 2·(vector·normal)·normal.</param>
    public static void Reflect(ref Vector3 vector, ref Vector3 normal, out Vector3 result) => result = Reflect(vector, normal);

    /// <summary>The <c>ref</c> form of <see cref="Add(Vector3, Vector3)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">value1 + value2.</param>
    public static void Add(ref Vector3 value1, ref Vector3 value2, out Vector3 result) => result = value1 + value2;

    /// <summary>The <c>ref</c> form of <see cref="Subtract(Vector3, Vector3)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">value1 − value2.</param>
    public static void Subtract(ref Vector3 value1, ref Vector3 value2, out Vector3 result) => result = value1 - value2;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Vector3, Vector3)"/>.</summary>
    /// <param name="value1">First vector.</param>
    /// <param name="value2">Second vector.</param>
    /// <param name="result">The component-wise product.</param>
    public static void Multiply(ref Vector3 value1, ref Vector3 value2, out Vector3 result) => result = value1 * value2;

    /// <summary>The <c>ref</c> form of <see cref="Multiply(Vector3, float)"/>.</summary>
    /// <param name="value1">The vector.</param>
    /// <param name="scaleFactor">The factor.</param>
    /// <param name="result">value1·scaleFactor.</param>
    public static void Multiply(ref Vector3 value1, float scaleFactor, out Vector3 result) => result = value1 * scaleFactor;

    /// <summary>The <c>ref</c> form of <see cref="Divide(Vector3, Vector3)"/>.</summary>
    /// <param name="value1">Dividend.</param>
    /// <param name="value2">Divisor.</param>
    /// <param name="result">The component-wise quotient.</param>
    public static void Divide(ref Vector3 value1, ref Vector3 value2, out Vector3 result) => result = value1 / value2;

    /// <summary>The <c>ref</c> form of <see cref="Divide(Vector3, float)"/>.</summary>
    /// <param name="value1">Dividend.</param>
    /// <param name="divider">Divisor.</param>
    /// <param name="result">value1 / divider.</param>
    public static void Divide(ref Vector3 value1, float divider, out Vector3 result) => result = value1 / divider;

    /// <summary>The <c>ref</c> form of <see cref="Negate(Vector3)"/>.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="result">−value.</param>
    public static void Negate(ref Vector3 value, out Vector3 result) => result = -value;

    // A cubic spline of four control values and a position (MathHelper.CatmullRom or MathHelper.Hermite), component by component.
    private static Vector3 Spline(Vector3 a, Vector3 b, Vector3 c, Vector3 d, float amount, Func<float, float, float, float, float, float> spline) =>
        new(spline(a.X, b.X, c.X, d.X, amount), spline(a.Y, b.Y, c.Y, d.Y, amount), spline(a.Z, b.Z, c.Z, d.Z, amount));
}
