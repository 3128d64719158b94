namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// A shape of the test reference, in double precision: a convex core (one point, a segment, or a
/// counter-clockwise polygon) dilated by <see cref="Radius"/>. Circles are a point core with a
/// radius; boxes, 8-DOPs, polygons and segments have radius 0. Built from the same float
/// numbers that are given to the library, but by independent code.
/// </summary>
public sealed class ReferenceShape
{
    private readonly Point2[] _core;

    private ReferenceShape(Point2[] core, double radius)
    {
        _core = core;
        Radius = radius;
    }

    /// <summary>The same shape moved by <paramref name="offset"/>, exactly in double (the core's points shifted, the radius kept).</summary>
    public ReferenceShape Translated(Point2 offset) => new(_core.Select(p => p + offset).ToArray(), Radius);

    /// <summary>The vertices of the convex core, counter-clockwise, with no repeated or collinear points.</summary>
    public IReadOnlyList<Point2> Core => _core;

    /// <summary>The dilation radius, mm (0 for everything but circles).</summary>
    public double Radius { get; }

    /// <summary>The mean of the core vertices.</summary>
    public Point2 Centre => new(_core.Average(p => p.X), _core.Average(p => p.Y));

    /// <summary>The radius of the circle around <see cref="Centre"/> that holds the whole shape.</summary>
    public double BoundingRadius
    {
        get
        {
            Point2 c = Centre;
            return _core.Max(p => Point2.Distance(p, c)) + Radius;
        }
    }

    /// <summary>A disc.</summary>
    public static ReferenceShape Circle(Vector2 center, float radius) => new([Point2.From(center)], radius);

    /// <summary>A box min ≤ p ≤ max.</summary>
    public static ReferenceShape Aabb(Vector2 min, Vector2 max) =>
        FromPoints([Point2.From(min), new(max.X, min.Y), Point2.From(max), new(min.X, max.Y)]);

    /// <summary>A segment.</summary>
    public static ReferenceShape Segment(Vector2 a, Vector2 b) => FromPoints([Point2.From(a), Point2.From(b)]);

    /// <summary>The convex hull of the given points (a convex polygon given in either winding).</summary>
    public static ReferenceShape Polygon(IEnumerable<Vector2> vertices) => FromPoints(vertices.Select(Point2.From));

    /// <summary>The convex hull of points given in double precision.</summary>
    public static ReferenceShape FromPoints(IEnumerable<Point2> points) => new(ReferenceGeometry.ConvexHull(points), 0);

    /// <summary>
    /// The 8-DOP min[i] ≤ p·aᵢ ≤ max[i] with a = (1, 0), (0, 1), (√½, √½), (√½, −√½), computed by
    /// clipping the box of the first two slabs with the four diagonal half-planes in double.
    /// </summary>
    public static ReferenceShape KDop8(IReadOnlyList<double> min, IReadOnlyList<double> max)
    {
        IReadOnlyList<Point2> p = [new(min[0], min[1]), new(max[0], min[1]), new(max[0], max[1]), new(min[0], max[1])];
        double h = Math.Sqrt(0.5);
        Point2 d2 = new(h, h), d3 = new(h, -h);
        p = ReferenceGeometry.ClipHalfPlane(p, d2, max[2]);
        p = ReferenceGeometry.ClipHalfPlane(p, -d2, -min[2]);
        p = ReferenceGeometry.ClipHalfPlane(p, d3, max[3]);
        p = ReferenceGeometry.ClipHalfPlane(p, -d3, -min[3]);
        if (p.Count == 0)
        {
            throw new ArgumentException("the slabs have no common point");
        }

        return FromPoints(p);
    }

    /// <summary>The tightest 8-DOP around a point set, with the slabs computed in double.</summary>
    public static ReferenceShape KDop8OfPoints(IEnumerable<Vector2> points)
    {
        var min = new[] { double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity };
        var max = new[] { double.NegativeInfinity, double.NegativeInfinity, double.NegativeInfinity, double.NegativeInfinity };
        foreach (var v in points)
        {
            var proj = SlabProjections(Point2.From(v));
            for (int i = 0; i < 4; i++)
            {
                min[i] = Math.Min(min[i], proj[i]);
                max[i] = Math.Max(max[i], proj[i]);
            }
        }

        return KDop8(min, max);
    }

    /// <summary>p·aᵢ for the four 8-DOP axes, in double.</summary>
    public static double[] SlabProjections(Point2 p)
    {
        double h = Math.Sqrt(0.5);
        return [p.X, p.Y, (p.X + p.Y) * h, (p.X - p.Y) * h];
    }

    /// <summary>
    /// Signed distance from <paramref name="p"/> to the shape's boundary, mm: negative inside,
    /// positive outside. (For a flat shape, 0 on it.)
    /// </summary>
    public double SignedDistance(Point2 p)
    {
        Point2 q = ReferenceGeometry.ClosestOnCore(_core, p, out bool inside);
        if (!inside)
        {
            return Point2.Distance(p, q) - Radius;
        }

        double nearest = double.PositiveInfinity;
        for (int i = 0; i < _core.Length; i++)
        {
            nearest = Math.Min(nearest, -ReferenceGeometry.EdgeSeparation(_core, i, p));
        }

        return -nearest - Radius;
    }

    /// <summary>True when p is inside the shape or within <paramref name="tolerance"/> mm of it.</summary>
    public bool Contains(Point2 p, double tolerance) => SignedDistance(p) <= tolerance;

    /// <summary>The extent of the shape along the unit <paramref name="axis"/>: [min, max] of p·axis.</summary>
    public (double Min, double Max) Project(Point2 axis)
    {
        double lo = _core.Min(p => Point2.Dot(p, axis)) - Radius;
        double hi = _core.Max(p => Point2.Dot(p, axis)) + Radius;
        return (lo, hi);
    }

    /// <inheritdoc />
    public override string ToString() =>
        $"core [{string.Join(", ", _core.Select(p => p.ToString()))}] radius {Radius:R}";
}
