namespace URWPGSim2D.Strategies.Tests.Sensing;

/// <summary>
/// One body in double: a disc (analytic), one or more convex counter-clockwise polygons (a point is
/// inside when strictly left of every edge; distances by brute force over boundary samples
/// <see cref="SensedScene.SamplesPerMm"/> per mm), or a border (the half-plane beyond one side of
/// the field; the distance of a point of the field is its gap to that side's line).
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

    /// <summary>The smallest distance between two polygon or disc bodies by brute force over both boundaries (0 when one contains a sample of the other).</summary>
    public static double Gap(Truth a, Truth b)
    {
        var sa = a.BoundaryPoints();
        var sb = b.BoundaryPoints();
        if (sa.Any(b.Inside) || sb.Any(a.Inside))
        {
            return 0;
        }

        double best = double.PositiveInfinity;
        foreach (var p in sa)
        {
            foreach (var q in sb)
            {
                best = Math.Min(best, Hypot(p.X - q.X, p.Y - q.Y));
            }
        }

        return best;
    }

    public static double Hypot(double x, double y) => Math.Sqrt((x * x) + (y * y));

    private List<(double X, double Y)> BoundaryPoints()
    {
        if (!IsDisc)
        {
            return Samples.SelectMany(s => s).ToList();
        }

        int n = (int)Math.Ceiling(2 * Math.PI * _radius * SensedScene.SamplesPerMm);
        return Enumerable.Range(0, n).Select(k => (_center.X + (_radius * Math.Cos(2 * Math.PI * k / n)), _center.Y + (_radius * Math.Sin(2 * Math.PI * k / n)))).ToList();
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
