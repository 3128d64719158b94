namespace URWPGSim2D.Collision.Tests.Queries;

/// <summary>
/// Double-precision truths for the queries, independent of the library's code: the gap from the
/// reference Minkowski difference, dense samples of the boundaries, and first roots of convex
/// functions along a line (signed distance of a point moving along a ray, signed gap of a shape
/// moving along a translation) by ternary search and bisection.
/// </summary>
internal static class QueryReference
{
    /// <summary>The signed gap between two shapes: the distance when apart, minus the depth when they overlap.</summary>
    public static double Gap(ReferenceShape a, ReferenceShape b) => -ReferenceGeometry.Contact(a, b).SignedDepth;

    /// <summary>The smallest gap over every pair of parts (a fish is its leaves).</summary>
    public static double Gap(IReadOnlyList<ReferenceShape> a, IReadOnlyList<ReferenceShape> b) =>
        a.SelectMany(x => b, (x, y) => Gap(x, y)).Min();

    /// <summary>The leaves of a fish as reference polygons.</summary>
    public static ReferenceShape[] Leaves(FishModel fish) =>
        Enum.GetValues<FishPart>().Select(p => ReferenceShape.Polygon(fish.GetLeaf(p).ToArray())).ToArray();

    /// <summary><paramref name="count"/> points evenly spread along the boundary of a shape.</summary>
    public static Point2[] BoundarySamples(ReferenceShape shape, int count)
    {
        var core = shape.Core;
        var points = new List<Point2>(count + 8);
        if (core.Count == 1)
        {
            for (int i = 0; i < count; i++)
            {
                points.Add(core[0] + Point2.FromAngle(2 * Math.PI * i / count) * shape.Radius);
            }

            return [.. points];
        }

        double perimeter = 0;
        for (int i = 0; i < core.Count; i++)
        {
            perimeter += Point2.Distance(core[i], core[(i + 1) % core.Count]);
        }

        for (int i = 0; i < core.Count; i++)
        {
            Point2 p = core[i], q = core[(i + 1) % core.Count];
            int n = Math.Max(1, (int)Math.Ceiling(count * Point2.Distance(p, q) / perimeter));
            for (int k = 0; k < n; k++)
            {
                points.Add(p + ((q - p) * ((double)k / n)));
            }
        }

        return [.. points];
    }

    /// <summary>The largest gap between neighbouring samples of <see cref="BoundarySamples"/>.</summary>
    public static double Spacing(Point2[] samples)
    {
        double s = 0;
        for (int i = 0; i < samples.Length; i++)
        {
            s = Math.Max(s, Point2.Distance(samples[i], samples[(i + 1) % samples.Length]));
        }

        return s;
    }

    /// <summary>The smallest distance between two sample sets (brute force).</summary>
    public static double SampledDistance(Point2[] a, Point2[] b)
    {
        double best = double.PositiveInfinity;
        foreach (var p in a)
        {
            foreach (var q in b)
            {
                double dx = p.X - q.X, dy = p.Y - q.Y;
                best = Math.Min(best, (dx * dx) + (dy * dy));
            }
        }

        return Math.Sqrt(best);
    }

    /// <summary>
    /// The first t in [0, 1] where the convex function <paramref name="f"/> reaches 0 from above,
    /// or null when it stays above <paramref name="miss"/> (or starts ≤ 0: then 0).
    /// </summary>
    public static double? FirstRoot(Func<double, double> f, double miss = 0)
    {
        if (f(0) <= 0)
        {
            return 0;
        }

        double lo = 0, hi = 1;
        for (int i = 0; i < 200; i++)
        {
            double m1 = lo + ((hi - lo) / 3), m2 = hi - ((hi - lo) / 3);
            if (f(m1) <= f(m2))
            {
                hi = m2;
            }
            else
            {
                lo = m1;
            }
        }

        double tMin = (lo + hi) / 2;
        if (f(tMin) > miss)
        {
            return null;
        }

        lo = 0;
        hi = tMin;
        for (int i = 0; i < 200; i++)
        {
            double m = (lo + hi) / 2;
            if (f(m) > 0)
            {
                lo = m;
            }
            else
            {
                hi = m;
            }
        }

        return hi;
    }

    public static Point2 At(Vector2 from, Vector2 to, double t) => Point2.From(from) + ((Point2.From(to) - Point2.From(from)) * t);
}
