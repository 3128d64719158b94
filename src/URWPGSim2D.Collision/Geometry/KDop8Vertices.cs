namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// The polygon of an 8-DOP, computed in double precision: the region min ≤ p·aᵢ ≤ max, its
/// tight slab values, and its edges, each lying on one of the eight slab lines and carrying
/// that line's exact outward normal.
/// </summary>
/// <remarks>
/// The eight lines, counter-clockwise by outward normal, are dₖ·p = hₖ with dₖ at k·45° from +x.
/// After the slabs are tightened (every line touches the region), vertex k is where line k meets
/// line k+1, and the edge on line k runs from vertex k−1 to vertex k; edges of zero length (a
/// slab touching at a corner only) are dropped. No float slack is added, so the polygon is the
/// region itself up to the final rounding of each vertex to float (half a float ulp).
/// </remarks>
internal static class KDop8Vertices
{
    private const double Half = 0.70710678118654752440;

    // Relative tolerance of the double arithmetic: keeps single-point and flat regions (all of
    // whose slab bounds come from the same points) and merges corners that coincide.
    private const double Slack = 1e-12;

    private static readonly Vector2[] Normals =
    [
        new(1f, 0f), new(KDop8Diagonal, KDop8Diagonal), new(0f, 1f), new(-KDop8Diagonal, KDop8Diagonal),
        new(-1f, 0f), new(-KDop8Diagonal, -KDop8Diagonal), new(0f, -1f), new(KDop8Diagonal, -KDop8Diagonal),
    ];

    private const float KDop8Diagonal = (float)Half;

    /// <summary>
    /// Writes the vertices (counter-clockwise, at most 8) of the region min ≤ p·aᵢ ≤ max and the
    /// outward unit normal of the edge starting at each, and returns their count: 0 when the
    /// region is empty, 1 for a point (no normals), 2 for a segment (normals n and −n).
    /// <paramref name="tightMin"/> and <paramref name="tightMax"/> receive the tight slab values:
    /// a slab that touches the region keeps its value exactly; one that was loose is moved in to
    /// the region, rounded outward to float.
    /// </summary>
    public static int Compute(Vector4 min, Vector4 max, Span<Vector2> vertices, Span<Vector2> normals, out Vector4 tightMin, out Vector4 tightMax)
    {
        Span<double> lo = stackalloc double[4];
        Span<double> hi = stackalloc double[4];
        double scale = Widen(min, max, lo, hi);

        double tol = Slack * scale;
        Span<Vector2D> region = stackalloc Vector2D[12];
        int n = ClipBox(lo, hi, tol, region);
        tightMin = min;
        tightMax = max;
        if (n == 0)
        {
            return 0;
        }

        // Tight slabs from the region's vertices, never outside the given ones.
        Span<double> tlo = stackalloc double[4];
        Span<double> thi = stackalloc double[4];
        for (int i = 0; i < 4; i++)
        {
            tlo[i] = double.PositiveInfinity;
            thi[i] = double.NegativeInfinity;
        }

        foreach (var p in region[..n])
        {
            for (int i = 0; i < 4; i++)
            {
                double d = Project(p, i);
                tlo[i] = Math.Min(tlo[i], d);
                thi[i] = Math.Max(thi[i], d);
            }
        }

        for (int i = 0; i < 4; i++)
        {
            tlo[i] = Math.Max(tlo[i], lo[i]);
            thi[i] = Math.Min(thi[i], hi[i]);
            tightMin[i] = tlo[i] - lo[i] <= tol ? min[i] : RoundDown(tlo[i]);
            tightMax[i] = hi[i] - thi[i] <= tol ? max[i] : RoundUp(thi[i]);
        }

        // Line k: dₖ·p = hₖ; vertex k = line k ∩ line k+1.
        Span<double> h = [thi[0], thi[2], thi[1], -tlo[3], -tlo[0], -tlo[2], -tlo[1], thi[3]];
        Span<Vector2D> corner = stackalloc Vector2D[8];
        for (int k = 0; k < 8; k++)
        {
            corner[k] = Meet(k, h[k], h[(k + 1) & 7]);
        }

        int count = 0;
        for (int k = 0; k < 8; k++)
        {
            // Edge on line k runs from corner k−1 to corner k.
            Vector2D from = corner[(k + 7) & 7], to = corner[k];
            Vector2 fromF = from.ToFloat(), toF = to.ToFloat();
            if (Vector2D.Distance(from, to) > tol && fromF != toF)
            {
                vertices[count] = fromF;
                normals[count] = Normals[k];
                count++;
            }
        }

        if (count == 0)
        {
            vertices[0] = corner[0].ToFloat();
            return 1;
        }

        return count;
    }

    /// <summary>
    /// The area centroid of the region min ≤ p·aᵢ ≤ max (the vertex mean when it has no area),
    /// computed in double: the action point of two overlapping slab sets. False when the region
    /// is empty.
    /// </summary>
    public static bool RegionCentroid(Vector4 min, Vector4 max, out Vector2 centroid)
    {
        Span<double> lo = stackalloc double[4];
        Span<double> hi = stackalloc double[4];
        double scale = Widen(min, max, lo, hi);

        Span<Vector2D> p = stackalloc Vector2D[12];
        int n = ClipBox(lo, hi, Slack * scale, p);
        if (n == 0)
        {
            centroid = default;
            return false;
        }

        // Fan from the first vertex, relative to it.
        Vector2D o = p[0];
        double area2 = 0, sx = 0, sy = 0, mx = 0, my = 0;
        for (int i = 1; i < n; i++)
        {
            double ex = p[i].X - o.X, ey = p[i].Y - o.Y;
            mx += ex;
            my += ey;
            if (i + 1 < n)
            {
                double fx = p[i + 1].X - o.X, fy = p[i + 1].Y - o.Y;
                double w = ex * fy - ey * fx;
                area2 += w;
                sx += (ex + fx) * w;
                sy += (ey + fy) * w;
            }
        }

        double extent = Math.Max(hi[0] - lo[0], hi[1] - lo[1]);
        centroid = area2 > 1e-12 * extent * extent
            ? new Vector2((float)(o.X + sx / (3 * area2)), (float)(o.Y + sy / (3 * area2)))
            : new Vector2((float)(o.X + mx / n), (float)(o.Y + my / n));
        return true;
    }

    /// <summary>p·aᵢ in double for the four axes (1, 0), (0, 1), (√½, √½), (√½, −√½).</summary>
    public static double Project(double x, double y, int axis) => axis switch
    {
        0 => x,
        1 => y,
        2 => (x + y) * Half,
        _ => (x - y) * Half,
    };

    /// <summary>The largest float not above x.</summary>
    public static float RoundDown(double x)
    {
        float f = (float)x;
        return f > x ? MathF.BitDecrement(f) : f;
    }

    /// <summary>The smallest float not below x.</summary>
    public static float RoundUp(double x)
    {
        float f = (float)x;
        return f < x ? MathF.BitIncrement(f) : f;
    }

    private static double Project(Vector2D p, int axis) => Project(p.X, p.Y, axis);

    // The box of slabs 0 and 1 clipped by the four diagonal half-planes (each loosened by tol).
    private static int ClipBox(ReadOnlySpan<double> lo, ReadOnlySpan<double> hi, double tol, Span<Vector2D> output)
    {
        Span<Vector2D> a = stackalloc Vector2D[12];
        Span<Vector2D> b = stackalloc Vector2D[12];
        a[0] = new(lo[0], lo[1]);
        a[1] = new(hi[0], lo[1]);
        a[2] = new(hi[0], hi[1]);
        a[3] = new(lo[0], hi[1]);
        int n = 4;
        n = Clip(a[..n], b, new(Half, Half), hi[2] + tol);
        n = Clip(b[..n], a, new(-Half, -Half), -lo[2] + tol);
        n = Clip(a[..n], b, new(Half, -Half), hi[3] + tol);
        n = Clip(b[..n], a, new(-Half, Half), -lo[3] + tol);
        a[..n].CopyTo(output);
        return n;
    }

    // Sutherland–Hodgman: the part of `input` with p·nrm ≤ offset.
    private static int Clip(ReadOnlySpan<Vector2D> input, Span<Vector2D> output, Vector2D nrm, double offset)
    {
        int count = 0;
        if (input.IsEmpty)
        {
            return 0;
        }

        Vector2D prev = input[^1];
        double prevDist = Vector2D.Dot(prev, nrm) - offset;
        foreach (var cur in input)
        {
            double curDist = Vector2D.Dot(cur, nrm) - offset;
            if ((curDist <= 0) != (prevDist <= 0))
            {
                double t = prevDist / (prevDist - curDist);
                output[count++] = new(prev.X + (cur.X - prev.X) * t, prev.Y + (cur.Y - prev.Y) * t);
            }

            if (curDist <= 0)
            {
                output[count++] = cur;
            }

            prev = cur;
            prevDist = curDist;
        }

        return count;
    }

    // Where line k (dₖ·p = hk) meets line k+1 (dₖ₊₁·p = hk1); the determinant is sin 45° = √½.
    private static Vector2D Meet(int k, double hk, double hk1)
    {
        Vector2D d0 = Direction(k), d1 = Direction(k + 1);
        double x = (hk * d1.Y - d0.Y * hk1) / Half;
        double y = (d0.X * hk1 - hk * d1.X) / Half;
        return new(x, y);
    }

    private static Vector2D Direction(int k) => (k & 7) switch
    {
        0 => new(1, 0),
        1 => new(Half, Half),
        2 => new(0, 1),
        3 => new(-Half, Half),
        4 => new(-1, 0),
        5 => new(-Half, -Half),
        6 => new(0, -1),
        _ => new(Half, -Half),
    };

    private readonly record struct Vector2D(double X, double Y)
    {
        public static double Dot(Vector2D a, Vector2D b) => a.X * b.X + a.Y * b.Y;

        public static double Distance(Vector2D a, Vector2D b) => Math.Sqrt((a.X - b.X) * (a.X - b.X) + (a.Y - b.Y) * (a.Y - b.Y));

        public Vector2 ToFloat() => new((float)X, (float)Y);
    }

    // The slabs' bounds in double, and the scale of their largest magnitude (at least 1).
    private static double Widen(Vector4 min, Vector4 max, Span<double> lo, Span<double> hi)
    {
        double scale = 1;
        for (int i = 0; i < 4; i++)
        {
            lo[i] = min[i];
            hi[i] = max[i];
            scale = Math.Max(scale, Math.Max(Math.Abs(lo[i]), Math.Abs(hi[i])));
        }

        return scale;
    }
}
