namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// A seeded generator of random <see cref="TestShape"/>s and shape pairs within the issue's
/// ranges: sizes 5 to 1,600 mm (log-uniform), coordinates up to ±25,000 mm, rotated convex
/// polygons with 3 to 16 vertices (Valtr's algorithm, then stretched and rotated).
/// </summary>
/// <remarks>
/// Usage: <c>var gen = new RandomShapes(seed); var (a, b, scenario) = gen.Pair(ShapeKind.Circle, ShapeKind.Polygon);</c>
/// then compare <c>CollisionDetector.Detect(a.Shape, b.Shape)</c> with
/// <c>ReferenceGeometry.Contact(a.Reference, b.Reference)</c>. The same seed gives the same shapes.
/// </remarks>
public sealed class RandomShapes
{
    /// <summary>Smallest shape size, mm.</summary>
    public const double MinSize = 5;

    /// <summary>Largest shape size, mm.</summary>
    public const double MaxSize = 1600;

    /// <summary>Largest absolute coordinate of any generated point, mm.</summary>
    public const double MaxCoordinate = 25000;

    private readonly Random _random;

    /// <summary>Creates a generator; the same seed always gives the same sequence.</summary>
    public RandomShapes(int seed) => _random = new Random(seed);

    /// <summary>Uniform in [lo, hi).</summary>
    public double Uniform(double lo, double hi) => lo + (hi - lo) * _random.NextDouble();

    /// <summary>Log-uniform in [lo, hi).</summary>
    public double LogUniform(double lo, double hi) => lo * Math.Exp(Math.Log(hi / lo) * _random.NextDouble());

    /// <summary>An integer in [lo, hi].</summary>
    public int Int(int lo, int hi) => _random.Next(lo, hi + 1);

    /// <summary>A shape size (longest extent), log-uniform in [<see cref="MinSize"/>, <see cref="MaxSize"/>].</summary>
    public double Size() => LogUniform(MinSize, MaxSize);

    /// <summary>A uniformly random unit vector.</summary>
    public Point2 Direction() => Point2.FromAngle(Uniform(0, 2 * Math.PI));

    /// <summary>A random shape of the given kind, centred near <paramref name="centre"/>, with longest extent about <paramref name="size"/>.</summary>
    public TestShape Create(ShapeKind kind, Point2 centre, double size) => kind switch
    {
        ShapeKind.Circle => TestShape.Circle(centre.ToVector2(), (float)(size / 2)),
        ShapeKind.Aabb => CreateAabb(centre, size),
        ShapeKind.KDop8 => _random.Next(2) == 0 ? CreateKDop8FromSlabs(centre, size) : CreateKDop8FromPoints(centre, size),
        ShapeKind.Polygon => TestShape.Polygon(ConvexPolygonVertices(centre, size, Int(3, 16))),
        _ => CreateSegment(centre, size),
    };

    /// <summary>
    /// A random pair: <paramref name="kindA"/> and <paramref name="kindB"/> placed by a random
    /// <see cref="PairScenario"/> somewhere in ±<see cref="MaxCoordinate"/>.
    /// </summary>
    public (TestShape A, TestShape B, PairScenario Scenario) Pair(ShapeKind kindA, ShapeKind kindB)
    {
        double roll = _random.NextDouble();
        var scenario = roll < 0.45 ? PairScenario.Scattered
            : roll < 0.6 ? PairScenario.Containment
            : roll < 0.85 ? PairScenario.NearTouching
            : PairScenario.Apart;
        double sizeA = Size(), sizeB = Size();
        if (scenario == PairScenario.Containment)
        {
            double big = LogUniform(200, MaxSize);
            double small = Math.Max(MinSize, big / Uniform(4, 40));
            (sizeA, sizeB) = _random.Next(2) == 0 ? (big, small) : (small, big);
        }

        TestShape a0 = Create(kindA, Point2.Zero, sizeA);
        TestShape b0 = Create(kindB, Point2.Zero, sizeB);
        double reach = a0.Reference.BoundingRadius + b0.Reference.BoundingRadius;
        double distance = scenario switch
        {
            PairScenario.Containment => Uniform(0, 0.25) * Math.Max(a0.Reference.BoundingRadius, b0.Reference.BoundingRadius),
            PairScenario.Apart => reach * Uniform(1.001, 1.3),
            _ => reach * Uniform(0, 1.05),
        };
        Point2 placeB = a0.Reference.Centre - b0.Reference.Centre + Direction() * distance;

        // Somewhere in the field such that both shapes stay within ±MaxCoordinate.
        var (loX, hiX) = Extent(a0, b0, placeB, new Point2(1, 0));
        var (loY, hiY) = Extent(a0, b0, placeB, new Point2(0, 1));
        var shift = new Point2(
            Uniform(-MaxCoordinate - loX, MaxCoordinate - hiX),
            Uniform(-MaxCoordinate - loY, MaxCoordinate - hiY));
        TestShape a = a0.Translated(shift);
        TestShape b = b0.Translated(placeB + shift);

        if (scenario == PairScenario.NearTouching)
        {
            var contact = ReferenceGeometry.Contact(a.Reference, b.Reference);
            a = a.Translated(contact.Mtv + contact.Normal * Uniform(-0.03, 0.03));
        }

        return (a, b, scenario);
    }

    /// <summary>
    /// The vertices of a random convex polygon (Valtr's algorithm with <paramref name="count"/>
    /// vertices, less any that are nearly collinear with their neighbours), stretched by up to
    /// 4:1, rotated, scaled to diameter <paramref name="size"/> and centred on <paramref name="centre"/>;
    /// counter-clockwise or clockwise at random. Every vertex lies at least 0.2 % of the size
    /// inside every edge line it is not on, so float rounding anywhere in ±25,000 mm keeps it convex.
    /// </summary>
    public Vector2[] ConvexPolygonVertices(Point2 centre, double size, int count)
    {
        while (true)
        {
            Point2[] p = Valtr(count);
            double aspect = LogUniform(0.25, 1);
            double angle = Uniform(0, 2 * Math.PI);
            Point2 u = Point2.FromAngle(angle), w = u.RightPerp;
            p = p.Select(q => u * q.X + w * (q.Y * aspect)).ToArray();
            double diameter = p.SelectMany(q => p, (q, r) => Point2.Distance(q, r)).Max();
            p = PruneFlatVertices(p, 2.5e-3 * diameter);
            var v = p.Select(q => (centre + q * (size / diameter)).ToVector2()).ToArray();
            if (!HasMargin(v, 2e-3 * size))
            {
                continue;
            }

            if (_random.Next(2) == 0)
            {
                Array.Reverse(v);
            }

            return v;
        }
    }

    // The extent along `axis` of a together with b moved by `offsetB` (with 1 mm to spare for rounding).
    private static (double Lo, double Hi) Extent(TestShape a, TestShape b, Point2 offsetB, Point2 axis)
    {
        var pa = a.Reference.Project(axis);
        var pb = b.Reference.Project(axis);
        double d = Point2.Dot(offsetB, axis);
        return (Math.Min(pa.Min, pb.Min + d) - 1, Math.Max(pa.Max, pb.Max + d) + 1);
    }

    // Drops vertices that lie within `margin` of the chord of their neighbours (Valtr's vectors
    // can be almost parallel), as long as three remain.
    private static Point2[] PruneFlatVertices(Point2[] p, double margin)
    {
        var list = p.ToList();
        bool removed = true;
        while (removed && list.Count > 3)
        {
            removed = false;
            for (int i = 0; i < list.Count && list.Count > 3; i++)
            {
                Point2 prev = list[(i + list.Count - 1) % list.Count], next = list[(i + 1) % list.Count];
                Point2 chord = next - prev;
                if (Math.Abs(Point2.Cross(chord, list[i] - prev)) < margin * chord.Length)
                {
                    list.RemoveAt(i);
                    removed = true;
                }
            }
        }

        return list.ToArray();
    }

    // Every vertex not on edge i lies at least `margin` inside edge i's line, in either winding.
    private static bool HasMargin(Vector2[] v, double margin)
    {
        var p = v.Select(Point2.From).ToArray();
        int n = p.Length;
        double sign = 0;
        for (int i = 0; i < n; i++)
        {
            Point2 a = p[i], e = p[(i + 1) % n] - a;
            double len = e.Length;
            if (len < margin)
            {
                return false;
            }

            for (int j = 0; j < n; j++)
            {
                if (j == i || j == (i + 1) % n)
                {
                    continue;
                }

                double s = Point2.Cross(e, p[j] - a) / len;
                if (sign == 0)
                {
                    sign = Math.Sign(s);
                }

                if (s * sign < margin)
                {
                    return false;
                }
            }
        }

        return true;
    }

    // Valtr's random convex polygon: random x and y increments split into two monotone chains,
    // paired at random, sorted by angle and laid end to end. Returns a CCW polygon about (0, 0).
    private Point2[] Valtr(int n)
    {
        double[] xs = Increments(n);
        double[] ys = Increments(n);
        ys = ys.OrderBy(_ => _random.Next()).ToArray();
        var vectors = xs.Zip(ys, (x, y) => new Point2(x, y)).OrderBy(q => Math.Atan2(q.Y, q.X)).ToArray();
        var points = new Point2[n];
        Point2 at = Point2.Zero;
        for (int i = 0; i < n; i++)
        {
            points[i] = at;
            at += vectors[i];
        }

        Point2 mean = new(points.Average(q => q.X), points.Average(q => q.Y));
        return points.Select(q => q - mean).ToArray();
    }

    // n signed increments summing to 0, from n sorted uniforms split into two chains.
    private double[] Increments(int n)
    {
        var s = Enumerable.Range(0, n).Select(_ => _random.NextDouble()).OrderBy(x => x).ToArray();
        var result = new List<double>(n);
        double top = s[0], bottom = s[0];
        for (int i = 1; i < n - 1; i++)
        {
            if (_random.Next(2) == 0)
            {
                result.Add(s[i] - top);
                top = s[i];
            }
            else
            {
                result.Add(bottom - s[i]);
                bottom = s[i];
            }
        }

        result.Add(s[n - 1] - top);
        result.Add(bottom - s[n - 1]);
        return result.ToArray();
    }

    private TestShape CreateAabb(Point2 centre, double size)
    {
        double w = size, h = size * LogUniform(0.1, 1);
        if (_random.Next(2) == 0)
        {
            (w, h) = (h, w);
        }

        return TestShape.Aabb(new Point2(centre.X - w / 2, centre.Y - h / 2).ToVector2(), new Point2(centre.X + w / 2, centre.Y + h / 2).ToVector2());
    }

    private TestShape CreateSegment(Point2 centre, double size)
    {
        Point2 half = Direction() * (size / 2);
        return TestShape.Segment((centre - half).ToVector2(), (centre + half).ToVector2());
    }

    // A box cut by the two diagonal slabs (sometimes not at all, sometimes by a loose slab).
    private TestShape CreateKDop8FromSlabs(Point2 centre, double size)
    {
        double w = size * LogUniform(0.25, 1), h = size * LogUniform(0.25, 1);
        double r = Math.Sqrt(0.5);
        double c2 = (centre.X + centre.Y) * r, c3 = (centre.X - centre.Y) * r, half = (w + h) / 2 * r;
        var min = new float[4];
        var max = new float[4];
        min[0] = (float)(centre.X - w / 2);
        max[0] = (float)(centre.X + w / 2);
        min[1] = (float)(centre.Y - h / 2);
        max[1] = (float)(centre.Y + h / 2);
        min[2] = (float)(c2 - half * Cut());
        max[2] = (float)(c2 + half * Cut());
        min[3] = (float)(c3 - half * Cut());
        max[3] = (float)(c3 + half * Cut());
        return TestShape.KDop8(min, max);
    }

    // Where a diagonal slab lies, as a fraction of the box's own diagonal half-extent.
    private double Cut()
    {
        double roll = _random.NextDouble();
        return roll < 0.7 ? Uniform(0.3, 1) : roll < 0.85 ? 1 : Uniform(1, 1.3);
    }

    private TestShape CreateKDop8FromPoints(Point2 centre, double size)
    {
        int count = Int(2, 8);
        Point2 u = Direction(), w = u.RightPerp;
        double aspect = LogUniform(0.25, 1);
        var points = new Vector2[count];
        points[0] = (centre - u * (size / 2)).ToVector2();
        points[1] = (centre + u * (size / 2)).ToVector2();
        for (int i = 2; i < count; i++)
        {
            points[i] = (centre + u * (size * Uniform(-0.5, 0.5)) + w * (size * aspect * Uniform(-0.5, 0.5))).ToVector2();
        }

        return TestShape.KDop8OfPoints(points);
    }
}
