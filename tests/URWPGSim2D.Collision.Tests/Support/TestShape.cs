using System.Globalization;

namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// One shape under test: the library <see cref="URWPGSim2D.Collision.Shapes.Shape"/> and its independent
/// double-precision <see cref="ReferenceShape"/>, both built from the same float numbers (the
/// "spec"). <see cref="Translated"/> moves the spec and rebuilds both, so the reference always
/// describes exactly the floats the library was given.
/// </summary>
public sealed class TestShape
{
    private readonly Func<Point2, TestShape> _translate;

    private TestShape(ShapeKind kind, Shape shape, ReferenceShape reference, string description, Func<Point2, TestShape> translate)
    {
        Kind = kind;
        Shape = shape;
        Reference = reference;
        Description = description;
        _translate = translate;
    }

    /// <summary>Which of the five kinds this is.</summary>
    public ShapeKind Kind { get; }

    /// <summary>The library shape.</summary>
    public Shape Shape { get; }

    /// <summary>The reference shape (double precision, independent code).</summary>
    public ReferenceShape Reference { get; }

    /// <summary>A C#-like description with round-trip floats, for failure messages.</summary>
    public string Description { get; }

    /// <summary>A circle.</summary>
    public static TestShape Circle(Vector2 center, float radius) => new(
        ShapeKind.Circle,
        new Circle(center, radius),
        ReferenceShape.Circle(center, radius),
        $"new Circle({V(center)}, {F(radius)})",
        d => Circle(Move(center, d), radius));

    /// <summary>A box.</summary>
    public static TestShape Aabb(Vector2 min, Vector2 max) => new(
        ShapeKind.Aabb,
        new Aabb(min, max),
        ReferenceShape.Aabb(min, max),
        $"new Aabb({V(min)}, {V(max)})",
        d => Aabb(Move(min, d), Move(max, d)));

    /// <summary>A segment.</summary>
    public static TestShape Segment(Vector2 a, Vector2 b) => new(
        ShapeKind.Segment,
        new Segment(a, b),
        ReferenceShape.Segment(a, b),
        $"new Segment({V(a)}, {V(b)})",
        d => Segment(Move(a, d), Move(b, d)));

    /// <summary>A convex polygon (either winding).</summary>
    public static TestShape Polygon(Vector2[] vertices) => new(
        ShapeKind.Polygon,
        new ConvexPolygon(vertices),
        ReferenceShape.Polygon(vertices),
        $"new ConvexPolygon([{string.Join(", ", vertices.Select(V))}])",
        d => Polygon(vertices.Select(v => Move(v, d)).ToArray()));

    /// <summary>An 8-DOP from its slab bounds (the reference clips the exact slabs in double).</summary>
    public static TestShape KDop8(float[] min, float[] max) => new(
        ShapeKind.KDop8,
        new KDop8(min, max),
        ReferenceShape.KDop8(min.Select(x => (double)x).ToArray(), max.Select(x => (double)x).ToArray()),
        $"new KDop8([{string.Join(", ", min.Select(F))}], [{string.Join(", ", max.Select(F))}])",
        d =>
        {
            double[] p = ReferenceShape.SlabProjections(d);
            return KDop8(
                min.Select((x, i) => (float)(x + p[i])).ToArray(),
                max.Select((x, i) => (float)(x + p[i])).ToArray());
        });

    /// <summary>The 8-DOP of a point set (the reference computes the slabs in double).</summary>
    public static TestShape KDop8OfPoints(Vector2[] points) => new(
        ShapeKind.KDop8,
        global::URWPGSim2D.Collision.Shapes.KDop8.FromPoints(points),
        ReferenceShape.KDop8OfPoints(points),
        $"KDop8.FromPoints([{string.Join(", ", points.Select(V))}])",
        d => KDop8OfPoints(points.Select(v => Move(v, d)).ToArray()));

    /// <summary>The same shape with its spec moved by <paramref name="offset"/> (added in double, rounded to float).</summary>
    public TestShape Translated(Point2 offset) => _translate(offset);

    /// <inheritdoc />
    public override string ToString() => Description;

    private static Vector2 Move(Vector2 v, Point2 d) => new((float)(v.X + d.X), (float)(v.Y + d.Y));

    private static string F(float x) => x.ToString("R", CultureInfo.InvariantCulture) + "f";

    private static string V(Vector2 v) => $"new({F(v.X)}, {F(v.Y)})";
}
