namespace URWPGSim2D.Strategies.Tests.Sensing;

/// <summary>
/// One body in double: a disc (analytic), one or more convex counter-clockwise polygons (a point is
/// inside when strictly left of every edge; a point's distance by brute force over boundary samples
/// <see cref="SensedScene.SamplesPerMm"/> per mm, the gap between two bodies exact, edge against
/// edge), or a border (the half-plane beyond one side of the field; the distance of a point of the
/// field is its gap to that side's line).
/// </summary>
internal sealed class Truth
{
    private readonly (double X, double Y) _center;
    private readonly double _radius;
    private readonly int _side;
    private readonly double _hx, _hz;

    private Truth(SensedBody body, (double X, double Y) center, double radius, List<(double X, double Y)[]> polygons, int side, double hx, double hz)
    {
        Body = body;
        _center = center;
        _radius = radius;
        Polygons = polygons;
        _side = side;
        _hx = hx;
        _hz = hz;
        Samples = polygons.Select(Sample).ToList();
    }

    public SensedBody Body { get; }

    public List<(double X, double Y)[]> Polygons { get; }

    /// <summary>Each polygon's boundary samples.</summary>
    public List<(double X, double Y)[]> Samples { get; }

    public bool IsDisc => Polygons.Count == 0 && _side < 0;

    public bool IsBorder => _side >= 0;

    public static Truth Disc(SensedBody body, Vector2 center, float radius) => new(body, (center.X, center.Y), radius, [], -1, 0, 0);

    public static Truth Polygon(SensedBody body, List<(double X, double Y)[]> polygons) => new(body, default, 0, polygons, -1, 0, 0);

    public static Truth Border(int side, double hx, double hz) => new(SensedBody.Wall(side), default, 0, [], side, hx, hz);

    /// <summary>Whether the point is strictly inside the body.</summary>
    public bool Inside((double X, double Y) p)
    {
        if (IsBorder)
        {
            return _side switch
            {
                0 => p.Y < -_hz,
                1 => p.X > _hx,
                2 => p.Y > _hz,
                _ => p.X < -_hx,
            };
        }

        if (IsDisc)
        {
            return Hypot(p.X - _center.X, p.Y - _center.Y) < _radius;
        }

        return Polygons.Any(poly => InsidePolygon(poly, p));
    }

    /// <summary>The distance from a point of the field to the body (0 inside): analytic for discs and borders, brute force over the samples for polygons (at most 1/(2·SamplesPerMm) mm too large).</summary>
    public double Distance((double X, double Y) p)
    {
        if (IsBorder)
        {
            return Math.Max(0, _side switch
            {
                0 => p.Y + _hz,
                1 => _hx - p.X,
                2 => _hz - p.Y,
                _ => p.X + _hx,
            });
        }

        if (IsDisc)
        {
            return Math.Max(0, Hypot(p.X - _center.X, p.Y - _center.Y) - _radius);
        }

        if (Inside(p))
        {
            return 0;
        }

        double best = double.PositiveInfinity;
        foreach (var samples in Samples)
        {
            foreach (var q in samples)
            {
                best = Math.Min(best, Hypot(p.X - q.X, p.Y - q.Y));
            }
        }

        return best;
    }

    /// <summary>The distance from a point to the body's boundary (for a point the sensor says is on it).</summary>
    public double BoundaryDistance((double X, double Y) p)
    {
        if (IsBorder)
        {
            return _side is 0 or 2 ? Math.Abs(Math.Abs(p.Y) - _hz) : Math.Abs(Math.Abs(p.X) - _hx);
        }

        if (IsDisc)
        {
            return Math.Abs(Hypot(p.X - _center.X, p.Y - _center.Y) - _radius);
        }

        return Samples.SelectMany(s => s).Min(q => Hypot(p.X - q.X, p.Y - q.Y));
    }

    /// <summary>
    /// The smallest distance between two polygon or disc bodies, exact in double (no sampling): the
    /// least gap between a convex piece of one and a convex piece of the other. Two convex polygons are
    /// 0 apart when a vertex of one is strictly inside the other or two edges meet, else the least
    /// distance from an edge's end to an edge of the other; a disc is its centre's distance less its radius.
    /// </summary>
    public static double Gap(Truth a, Truth b)
    {
        if (a.IsDisc && b.IsDisc)
        {
            return Math.Max(0, Hypot(a._center.X - b._center.X, a._center.Y - b._center.Y) - a._radius - b._radius);
        }

        if (a.IsDisc || b.IsDisc)
        {
            var (disc, polygon) = a.IsDisc ? (a, b) : (b, a);
            return Math.Max(0, polygon.ExactDistance(disc._center) - disc._radius);
        }

        double best = double.PositiveInfinity;
        foreach (var pa in a.Polygons)
        {
            foreach (var pb in b.Polygons)
            {
                best = Math.Min(best, PolygonGap(pa, pb));
            }
        }

        return best;
    }

    public static double Hypot(double x, double y) => Math.Sqrt((x * x) + (y * y));

    // The exact distance from a point to the polygons (0 inside one).
    private double ExactDistance((double X, double Y) p)
    {
        if (Inside(p))
        {
            return 0;
        }

        double best = double.PositiveInfinity;
        foreach (var poly in Polygons)
        {
            for (int i = 0; i < poly.Length; i++)
            {
                best = Math.Min(best, SegmentDistance(p, poly[i], poly[(i + 1) % poly.Length]));
            }
        }

        return best;
    }

    private static double PolygonGap((double X, double Y)[] pa, (double X, double Y)[] pb)
    {
        if (pa.Any(v => InsidePolygon(pb, v)) || pb.Any(v => InsidePolygon(pa, v)))
        {
            return 0;
        }

        double best = double.PositiveInfinity;
        for (int i = 0; i < pa.Length; i++)
        {
            var a0 = pa[i];
            var a1 = pa[(i + 1) % pa.Length];
            for (int j = 0; j < pb.Length; j++)
            {
                var b0 = pb[j];
                var b1 = pb[(j + 1) % pb.Length];
                if (Cross(a0, a1, b0) * Cross(a0, a1, b1) < 0 && Cross(b0, b1, a0) * Cross(b0, b1, a1) < 0)
                {
                    return 0; // the edges cross (edges that only touch are 0 apart below)
                }

                best = Math.Min(best, Math.Min(
                    Math.Min(SegmentDistance(a0, b0, b1), SegmentDistance(a1, b0, b1)),
                    Math.Min(SegmentDistance(b0, a0, a1), SegmentDistance(b1, a0, a1))));
            }
        }

        return best;
    }

    // Twice the signed area of the triangle a, b, p: positive when p is left of a→b.
    private static double Cross((double X, double Y) a, (double X, double Y) b, (double X, double Y) p) =>
        ((b.X - a.X) * (p.Y - a.Y)) - ((b.Y - a.Y) * (p.X - a.X));

    // The distance from p to the segment a–b.
    private static double SegmentDistance((double X, double Y) p, (double X, double Y) a, (double X, double Y) b)
    {
        double dx = b.X - a.X, dy = b.Y - a.Y, squared = (dx * dx) + (dy * dy);
        double t = squared > 0 ? Math.Clamp((((p.X - a.X) * dx) + ((p.Y - a.Y) * dy)) / squared, 0, 1) : 0;
        return Hypot(p.X - (a.X + (t * dx)), p.Y - (a.Y + (t * dy)));
    }

    private static bool InsidePolygon((double X, double Y)[] poly, (double X, double Y) p)
    {
        for (int i = 0; i < poly.Length; i++)
        {
            var a = poly[i];
            var b = poly[(i + 1) % poly.Length];
            if (((b.X - a.X) * (p.Y - a.Y)) - ((b.Y - a.Y) * (p.X - a.X)) <= 0)
            {
                return false;
            }
        }

        return true;
    }

    private static (double X, double Y)[] Sample((double X, double Y)[] poly)
    {
        var points = new List<(double X, double Y)>();
        for (int i = 0; i < poly.Length; i++)
        {
            var a = poly[i];
            var b = poly[(i + 1) % poly.Length];
            int n = Math.Max(1, (int)Math.Ceiling(Hypot(b.X - a.X, b.Y - a.Y) * SensedScene.SamplesPerMm));
            for (int k = 0; k < n; k++)
            {
                points.Add((a.X + ((b.X - a.X) * k / n), a.Y + ((b.Y - a.Y) * k / n)));
            }
        }

        return [.. points];
    }
}
