using System;
using System.Numerics;
using URWPGSim2D.Collision.Shapes;

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
