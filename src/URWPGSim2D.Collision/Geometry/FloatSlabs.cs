using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// Conservative 8-DOP slabs of a point set in float, for bounding volumes rebuilt at every pose
/// (the exact, double-rounded slabs of <see cref="KDop8.Slabs"/> cost several times more).
/// Axes 0 and 1 are the coordinates themselves, so their minima and maxima are exact. A diagonal
/// projection fl(fl(x ± y)·fl(√½)) is within 3·2⁻²⁴·(|x| + |y|)·√½ (plus far smaller terms)
/// of the exact (x ± y)·√½, so moving the diagonal bounds outward by
/// 2⁻²² · (max |x| + max |y|) — more than that error plus the rounding of the move itself —
/// keeps every point inside.
/// </summary>
internal static class FloatSlabs
{
    /// <summary>2⁻²², the relative outward pad of the diagonal slabs.</summary>
    private const float DiagonalPad = 1f / 4194304f;

    /// <summary>Slabs of <paramref name="points"/> (at least one) on the four 8-DOP axes, never tighter than the points.</summary>
    public static void Of(ReadOnlySpan<Vector2> points, out Vector4 min, out Vector4 max)
    {
        if (!Vector128.IsHardwareAccelerated)
        {
            OfScalar(points, out min, out max);
            return;
        }

        Projections(points, out var lo, out var hi);
        var reach = Vector128.MaxNative(-lo, hi);
        var outward = Outward(reach.GetElement(0) + reach.GetElement(1));
        min = (lo - outward).AsVector4();
        max = (hi + outward).AsVector4();
    }

    /// <summary>
    /// The outward move (0, 0, pad, pad) that makes float projections safe for points with
    /// |x| + |y| ≤ <paramref name="extent"/>: pad = 2⁻²²·extent.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector128<float> Outward(float extent)
    {
        float pad = DiagonalPad * extent;
        return Vector128.Create(0f, 0f, pad, pad);
    }

    /// <summary>
    /// The least and greatest float projections (x, y, (x + y)·√½, (x − y)·√½) of the points (at
    /// least one), not yet moved outward (see <see cref="Outward"/>). Needs 128-bit vectors.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Projections(ReadOnlySpan<Vector2> points, out Vector128<float> lo, out Vector128<float> hi)
    {
        ref byte first = ref Unsafe.As<Vector2, byte>(ref MemoryMarshal.GetReference(points));
        if (Vector256.IsHardwareAccelerated && points.Length >= 2)
        {
            // Two points per vector, (x₀, y₀, x₁, y₁) twice → (x₀, y₀, x₀ + y₀, x₀ − y₀, x₁, …);
            // an odd count takes the last two points again (a repeat changes no minimum or maximum).
            var low = Vector256.Create(float.PositiveInfinity);
            var high = Vector256.Create(float.NegativeInfinity);
            int pairs = points.Length >> 1;
            for (int k = 0; k < pairs; k++)
            {
                Pair(ref Unsafe.Add(ref first, 16 * k), ref low, ref high);
            }

            if ((points.Length & 1) != 0)
            {
                Pair(ref Unsafe.Add(ref first, 8 * (points.Length - 2)), ref low, ref high);
            }

            lo = Vector128.MinNative(low.GetLower(), low.GetUpper());
            hi = Vector128.MaxNative(high.GetLower(), high.GetUpper());
            return;
        }

        // Each point as (x, y, x, y) → (x, y, x + y, x − y) · (1, 1, √½, √½): the same roundings as the scalar path.
        var scale = Vector128.Create(1f, 1f, KDop8.Diagonal, KDop8.Diagonal);
        var sign = Vector128.Create(0f, 0f, 1f, -1f);
        lo = Vector128.Create(float.PositiveInfinity);
        hi = Vector128.Create(float.NegativeInfinity);
        for (int i = 0; i < points.Length; i++)
        {
            var p = Vector128.Create(Unsafe.ReadUnaligned<double>(ref Unsafe.Add(ref first, 8 * i))).AsSingle();
            var q = (Vector128.Shuffle(p, Vector128.Create(0, 1, 0, 0)) + (Vector128.Shuffle(p, Vector128.Create(1, 1, 1, 1)) * sign)) * scale;
            lo = Vector128.MinNative(lo, q);
            hi = Vector128.MaxNative(hi, q);
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Pair(ref byte at, ref Vector256<float> low, ref Vector256<float> high)
    {
        var scale = Vector256.Create(1f, 1f, KDop8.Diagonal, KDop8.Diagonal, 1f, 1f, KDop8.Diagonal, KDop8.Diagonal);
        var sign = Vector256.Create(0f, 0f, 1f, -1f, 0f, 0f, 1f, -1f);
        var pair = Vector128.LoadUnsafe(ref Unsafe.As<byte, float>(ref at));
        var p = Vector256.Create(pair, pair);
        var q = (Vector256.Shuffle(p, Vector256.Create(0, 1, 0, 0, 6, 7, 6, 6)) + (Vector256.Shuffle(p, Vector256.Create(1, 1, 1, 1, 7, 7, 7, 7)) * sign)) * scale;
        low = Vector256.MinNative(low, q);
        high = Vector256.MaxNative(high, q);
    }

    /// <summary>The same slabs without vector hardware.</summary>
    internal static void OfScalar(ReadOnlySpan<Vector2> points, out Vector4 min, out Vector4 max)
    {
        var scale = new Vector4(1f, 1f, KDop8.Diagonal, KDop8.Diagonal);
        Vector4 lo = new(float.PositiveInfinity), hi = new(float.NegativeInfinity);
        foreach (Vector2 p in points)
        {
            var q = new Vector4(p.X, p.Y, p.X + p.Y, p.X - p.Y) * scale;
            lo = Vector4.Min(lo, q);
            hi = Vector4.Max(hi, q);
        }

        float pad = DiagonalPad * (MathF.Max(-lo.X, hi.X) + MathF.Max(-lo.Y, hi.Y));
        var outward = new Vector4(0f, 0f, pad, pad);
        min = lo - outward;
        max = hi + outward;
    }
}
