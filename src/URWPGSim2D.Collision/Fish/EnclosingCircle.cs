using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Bounding circles for the fish's tree: the minimum enclosing circle of a few points
/// (incremental Welzl, no allocation; used once per fish size), and circles about a given
/// centre that reach the farthest point (used at every pose). Every
/// circle returned is grown by a few parts per million so that round-off never leaves a
/// point of what it bounds outside it.
/// </summary>
internal static class EnclosingCircle
{
    /// <summary>
    /// The minimum enclosing circle of <paramref name="points"/> (at least one point), mm.
    /// Incremental algorithm: whenever a point falls outside the current circle it must lie on
    /// the boundary of the circle of the points seen so far, which is rebuilt with it (then
    /// with two fixed points, then three). Putting the likely extreme points first keeps the
    /// rebuilds rare. The radius is finally the largest distance from the centre, plus slack.
    /// </summary>
    public static Circle Minimum(ReadOnlySpan<Vector2> points)
    {
        Vector2 o = points[0];
        Vector2 c = Vector2.Zero;
        float r2 = 0f;
        for (int i = 1; i < points.Length; i++)
        {
            Vector2 pi = points[i] - o;
            if (!Outside(pi, c, r2))
            {
                continue;
            }

            c = pi;
            r2 = 0f;
            for (int j = 0; j < i; j++)
            {
                Vector2 pj = points[j] - o;
                if (!Outside(pj, c, r2))
                {
                    continue;
                }

                c = 0.5f * (pi + pj);
                r2 = Vector2.DistanceSquared(pi, c);
                for (int k = 0; k < j; k++)
                {
                    Vector2 pk = points[k] - o;
                    if (Outside(pk, c, r2))
                    {
                        c = ThroughThree(pi, pj, pk);
                        r2 = Vector2.DistanceSquared(pi, c);
                    }
                }
            }
        }

        return Enclosing(points, o + c);
    }

    /// <summary>The circle centred at <paramref name="center"/> through the farthest of <paramref name="points"/>, plus slack.</summary>
    public static Circle Enclosing(ReadOnlySpan<Vector2> points, Vector2 center) => WithSlack(center, MathF.Sqrt(FarthestSquared(points, center)));

    /// <summary>
    /// The largest squared distance |p − c|² = dx·dx + dz·dz from <paramref name="center"/> to
    /// any of <paramref name="points"/> (0 for none). Four points per 256-bit vector (or two per
    /// 128-bit vector) where the hardware has them, with the same roundings as the point-by-point loop.
    /// </summary>
    public static float FarthestSquared(ReadOnlySpan<Vector2> points, Vector2 center)
    {
        float max2 = 0f;
        int i = 0;
        ref float first = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(points));
        if (Vector256.IsHardwareAccelerated && points.Length >= 4)
        {
            // Four points per vector; the last block overlaps the one before (a repeat changes no maximum).
            var c = Vector256.Create(center.X, center.Y, center.X, center.Y, center.X, center.Y, center.X, center.Y);
            var acc = Vector256<float>.Zero;
            for (int at = 0; ; at += 4)
            {
                at = Math.Min(at, points.Length - 4);
                var d = Vector256.LoadUnsafe(ref first, (nuint)(2 * at)) - c;
                var square = d * d;
                acc = Vector256.MaxNative(acc, square + Vector256.Shuffle(square, Vector256.Create(1, 0, 3, 2, 5, 4, 7, 6)));
                if (at == points.Length - 4)
                {
                    break;
                }
            }

            var two = Vector128.MaxNative(acc.GetLower(), acc.GetUpper());
            return MathF.Max(two.GetElement(0), two.GetElement(2));
        }

        if (Vector128.IsHardwareAccelerated && points.Length >= 2)
        {
            var c = Vector128.Create(center.X, center.Y, center.X, center.Y);
            var acc = Vector128<float>.Zero;
            for (; i + 2 <= points.Length; i += 2)
            {
                var d = Vector128.LoadUnsafe(ref first, (nuint)(2 * i)) - c;
                var square = d * d;
                acc = Vector128.MaxNative(acc, square + Vector128.Shuffle(square, Vector128.Create(1, 0, 3, 2)));
            }

            max2 = MathF.Max(acc.GetElement(0), acc.GetElement(2));
        }

        for (; i < points.Length; i++)
        {
            max2 = MathF.Max(max2, Vector2.DistanceSquared(points[i], center));
        }

        return max2;
    }

    /// <summary>Grows a radius by 2 ppm of the coordinates' magnitude (covers float round-off of the points and the centre).</summary>
    public static Circle WithSlack(Vector2 center, float radius)
    {
        float scale = radius + MathF.Max(MathF.Abs(center.X), MathF.Abs(center.Y));
        return Circle.Bounding(center, radius + 2e-6f * scale + 1e-6f);
    }

    // Outside with a relative tolerance, so that round-off on boundary points never triggers a rebuild.
    private static bool Outside(Vector2 p, Vector2 c, float r2) => Vector2.DistanceSquared(p, c) > r2 * (1f + 1e-6f);

    // The circumcentre of a triangle; for a (nearly) flat one, the middle of its longest side.
    private static Vector2 ThroughThree(Vector2 a, Vector2 b, Vector2 c)
    {
        Vector2 ab = b - a, ac = c - a;
        float d = 2f * (ab.X * ac.Y - ab.Y * ac.X);
        float ab2 = ab.LengthSquared(), ac2 = ac.LengthSquared();
        float bc2 = Vector2.DistanceSquared(b, c);
        if (MathF.Abs(d) <= 1e-6f * MathF.Max(ab2, ac2))
        {
            return bc2 >= ab2 && bc2 >= ac2 ? 0.5f * (b + c) : ab2 >= ac2 ? 0.5f * (a + b) : 0.5f * (a + c);
        }

        return a + new Vector2(ac.Y * ab2 - ab.Y * ac2, ab.X * ac2 - ac.X * ab2) / d;
    }
}
