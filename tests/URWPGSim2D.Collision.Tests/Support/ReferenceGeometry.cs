namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// Double-precision convex geometry written independently of the library (no shared code, no
/// float): convex hulls, half-plane clipping, closest points, and the penetration of two
/// <see cref="ReferenceShape"/>s computed by brute force from their Minkowski difference.
/// </summary>
/// <remarks>
/// Every reference shape is a convex core (a point, a segment or a polygon) dilated by a radius.
/// The Minkowski difference of a = Ca ⊕ disc(ra) and b = Cb ⊕ disc(rb) is H ⊕ disc(ra + rb), with
/// H = hull{p − q : p ∈ Ca, q ∈ Cb}. Translating a by t translates H by t, so a and b overlap
/// exactly when the origin is interior to H ⊕ disc(R), and the penetration depth is the distance
/// from the origin to the boundary of that set.
/// </remarks>
public static class ReferenceGeometry
{
    /// <summary>
    /// The convex hull of <paramref name="points"/>, counter-clockwise (x–z coordinates), with
    /// collinear and repeated points removed: 1 point, 2 points (a segment) or a polygon.
    /// </summary>
    public static Point2[] ConvexHull(IEnumerable<Point2> points)
    {
        var sorted = points.ToArray();
        Array.Sort(sorted, (u, v) => u.X != v.X ? u.X.CompareTo(v.X) : u.Y.CompareTo(v.Y));
        int unique = 0;
        foreach (var q in sorted)
        {
            if (unique == 0 || q != sorted[unique - 1])
            {
                sorted[unique++] = q;
            }
        }

        var p = sorted[..unique];
        if (p.Length <= 2)
        {
            return p;
        }

        var hull = new Point2[2 * p.Length];
        int k = 0;
        for (int i = 0; i < p.Length; i++)
        {
            while (k >= 2 && Point2.Cross(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0)
            {
                k--;
            }

            hull[k++] = p[i];
        }

        for (int i = p.Length - 2, lower = k + 1; i >= 0; i--)
        {
            while (k >= lower && Point2.Cross(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0)
            {
                k--;
            }

            hull[k++] = p[i];
        }

        // The last point repeats the first; a collinear set leaves [p0, pn, p0].
        return hull[..(k - 1)];
    }

    /// <summary>The part of the convex polygon <paramref name="polygon"/> where n·p ≤ offset (Sutherland–Hodgman).</summary>
    public static Point2[] ClipHalfPlane(IReadOnlyList<Point2> polygon, Point2 n, double offset)
    {
        var result = new List<Point2>(polygon.Count + 1);
        for (int i = 0; i < polygon.Count; i++)
        {
            Point2 cur = polygon[i];
            Point2 next = polygon[(i + 1) % polygon.Count];
            double dc = Point2.Dot(n, cur) - offset;
            double dn = Point2.Dot(n, next) - offset;
            if (dc <= 0)
            {
                result.Add(cur);
            }

            if ((dc < 0 && dn > 0) || (dc > 0 && dn < 0))
            {
                result.Add(cur + (next - cur) * (dc / (dc - dn)));
            }
        }

        return result.ToArray();
    }

    /// <summary>The point of segment [a, b] nearest to <paramref name="p"/>.</summary>
    public static Point2 ClosestOnSegment(Point2 a, Point2 b, Point2 p)
    {
        Point2 e = b - a;
        double len2 = e.LengthSquared;
        if (len2 == 0)
        {
            return a;
        }

        double t = Math.Clamp(Point2.Dot(p - a, e) / len2, 0, 1);
        return a + e * t;
    }

    /// <summary>
    /// The point of the (filled) convex core <paramref name="core"/> nearest to <paramref name="p"/>,
    /// and whether p lies inside the core or on its boundary (only possible for a polygon core).
    /// </summary>
    public static Point2 ClosestOnCore(IReadOnlyList<Point2> core, Point2 p, out bool inside)
    {
        inside = false;
        if (core.Count == 1)
        {
            return core[0];
        }

        if (core.Count == 2)
        {
            return ClosestOnSegment(core[0], core[1], p);
        }

        inside = true;
        for (int i = 0; i < core.Count; i++)
        {
            if (EdgeSeparation(core, i, p) > 0)
            {
                inside = false;
                break;
            }
        }

        if (inside)
        {
            return p;
        }

        Point2 best = core[0];
        double bestDist = double.PositiveInfinity;
        for (int i = 0; i < core.Count; i++)
        {
            Point2 q = ClosestOnSegment(core[i], core[(i + 1) % core.Count], p);
            double d = (q - p).LengthSquared;
            if (d < bestDist)
            {
                bestDist = d;
                best = q;
            }
        }

        return best;
    }

    /// <summary>Signed distance of p from the line of edge i (vertex i → i+1) of a CCW polygon: positive outside.</summary>
    public static double EdgeSeparation(IReadOnlyList<Point2> polygon, int i, Point2 p)
    {
        Point2 a = polygon[i];
        Point2 n = (polygon[(i + 1) % polygon.Count] - a).RightPerp.Normalized();
        return Point2.Dot(n, p - a);
    }

    /// <summary>The core of the Minkowski difference a − b: hull of all pairwise differences of core vertices.</summary>
    public static Point2[] MinkowskiDifferenceCore(ReferenceShape a, ReferenceShape b)
    {
        var d = new List<Point2>(a.Core.Count * b.Core.Count);
        foreach (var p in a.Core)
        {
            foreach (var q in b.Core)
            {
                d.Add(p - q);
            }
        }

        return ConvexHull(d);
    }

    /// <summary>
    /// The contact of <paramref name="a"/> and <paramref name="b"/>: the signed penetration depth
    /// (positive: overlap depth; negative: minus the gap) and the unit normal from b toward a,
    /// so that translating a by <see cref="ReferenceContact.Mtv"/> leaves the two just touching
    /// in both cases.
    /// </summary>
    public static ReferenceContact Contact(ReferenceShape a, ReferenceShape b)
    {
        Point2[] h = MinkowskiDifferenceCore(a, b);
        double r = a.Radius + b.Radius;
        Point2 q = ClosestOnCore(h, Point2.Zero, out bool inside);
        if (inside)
        {
            // Origin inside (or on) the polygon core: leave through the nearest edge line.
            int edge = 0;
            double nearest = double.PositiveInfinity;
            for (int i = 0; i < h.Length; i++)
            {
                double dist = -EdgeSeparation(h, i, Point2.Zero);
                if (dist < nearest)
                {
                    nearest = dist;
                    edge = i;
                }
            }

            Point2 outward = (h[(edge + 1) % h.Length] - h[edge]).RightPerp.Normalized();
            return new ReferenceContact(nearest + r, -outward);
        }

        double gap = q.Length;
        if (gap > 0)
        {
            return new ReferenceContact(r - gap, q / gap);
        }

        // The origin lies on a point or segment core (concentric circles, circle centre on a
        // segment): every direction (or both sides of the segment) is equally short.
        Point2 n = h.Length == 2 ? (h[1] - h[0]).RightPerp.Normalized() : new Point2(1, 0);
        return new ReferenceContact(r, n);
    }

    /// <summary>
    /// The distance a must move along the unit <paramref name="direction"/> until a and b stop
    /// overlapping (0 if they do not overlap): the exit distance of the ray from the origin along
    /// −direction out of the Minkowski difference H ⊕ disc(R).
    /// </summary>
    public static double DirectionalDepth(ReferenceShape a, ReferenceShape b, Point2 direction)
    {
        Point2[] h = MinkowskiDifferenceCore(a, b);
        double r = a.Radius + b.Radius;
        Point2 d = -direction.Normalized();
        if (r == 0)
        {
            if (h.Length < 3)
            {
                return 0;
            }

            double exit = double.PositiveInfinity;
            for (int i = 0; i < h.Length; i++)
            {
                Point2 n = (h[(i + 1) % h.Length] - h[i]).RightPerp.Normalized();
                double support = Point2.Dot(n, h[i]);
                if (support <= 0)
                {
                    return 0;
                }

                double rate = Point2.Dot(n, d);
                if (rate > 0)
                {
                    exit = Math.Min(exit, support / rate);
                }
            }

            return exit;
        }

        // H ⊕ disc(R) is the union of the discs on H's vertices and the rectangles on its edges;
        // the ray from an inside origin leaves it at the farthest exit from any of those pieces.
        if (ClosestOnCore(h, Point2.Zero, out _).Length >= r)
        {
            return 0;
        }

        double far = 0;
        foreach (Point2 v in h)
        {
            double along = Point2.Dot(d, v);
            double disc = along * along - v.LengthSquared + r * r;
            if (disc >= 0)
            {
                far = Math.Max(far, along + Math.Sqrt(disc));
            }
        }

        int edges = h.Length == 2 ? 1 : h.Length >= 3 ? h.Length : 0;
        for (int i = 0; i < edges; i++)
        {
            Point2 v0 = h[i];
            Point2 e = h[(i + 1) % h.Length] - v0;
            Point2 m = e.RightPerp.Normalized();
            double lo = 0, hi = double.PositiveInfinity;
            if (ClipSlab(e, v0, 0, e.LengthSquared, d, ref lo, ref hi) && ClipSlab(m, v0, -r, r, d, ref lo, ref hi) && lo <= hi)
            {
                far = Math.Max(far, hi);
            }
        }

        return far;
    }

    // Restricts [lo, hi] to the s with lower ≤ w·(s·d − v) ≤ upper; false when that is empty.
    private static bool ClipSlab(Point2 w, Point2 v, double lower, double upper, Point2 d, ref double lo, ref double hi)
    {
        double rate = Point2.Dot(w, d);
        double at0 = -Point2.Dot(w, v);
        if (Math.Abs(rate) < 1e-300)
        {
            return at0 >= lower && at0 <= upper;
        }

        double s0 = (lower - at0) / rate, s1 = (upper - at0) / rate;
        lo = Math.Max(lo, Math.Min(s0, s1));
        hi = Math.Min(hi, Math.Max(s0, s1));
        return true;
    }
}
