using System.Runtime.Intrinsics.X86;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// Conversions between the world X–Z plane (public <see cref="Vector3"/>, Y = 0) and the
/// 2D vectors used inside the library (<see cref="Vector2"/>: X = world X, Y = world Z).
/// </summary>
public static class XZPlane
{
    /// <summary>Maps a plane vector (x, z) to the world vector (x, 0, z).</summary>
    /// <param name="v">Plane vector: X = world X, Y = world Z.</param>
    /// <returns>The world vector with Y = 0.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3 ToWorld(Vector2 v) => new(v.X, 0f, v.Y);

    /// <summary>Maps a world vector (x, y, z) to the plane vector (x, z); Y is dropped.</summary>
    /// <param name="v">World vector.</param>
    /// <returns>The plane vector (X = world X, Y = world Z).</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector2 ToPlane(Vector3 v) => new(v.X, v.Z);

    /// <summary>
    /// <see cref="Vector2.Dot"/> with the same result bit for bit, without the hardware
    /// dot-product instruction on x86 (DPPS: about 15 cycles before the result is ready, against
    /// 7 for two multiplications and two additions). DPPS sums four lanes,
    /// (a.X·b.X + a.Y·b.Y) + (0 + 0), so a sum of −0 comes out as +0; the trailing + 0 does the same.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static float Dot(Vector2 a, Vector2 b) =>
        Sse.IsSupported ? ((a.X * b.X) + (a.Y * b.Y)) + 0f : Vector2.Dot(a, b);

    /// <summary>The 2D cross product a.X·b.Y − a.Y·b.X (the signed area of the parallelogram a, b).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static float Cross(Vector2 a, Vector2 b) => a.X * b.Y - a.Y * b.X;

    /// <summary>The outward normal of an edge walked counter-clockwise (in x–z coordinates): (d.Y, −d.X), not normalised.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static Vector2 RightPerp(Vector2 d) => new(d.Y, -d.X);
}
