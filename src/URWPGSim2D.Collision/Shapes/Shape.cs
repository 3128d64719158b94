using System.Diagnostics.CodeAnalysis;

namespace URWPGSim2D.Collision.Shapes;

/// <summary>
/// Any one of the five primitive shapes, for code that handles shapes it does not know in
/// advance (files, scenes). Each shape converts to it implicitly;
/// <see cref="CollisionDetector.Detect(in Shape, in Shape)"/> dispatches on the two kinds.
/// </summary>
public readonly struct Shape
{
    private readonly Circle _circle;
    private readonly Aabb _aabb;
    private readonly KDop8 _kdop;
    private readonly ConvexPolygon _polygon;
    private readonly Segment _segment;

    private Shape(ShapeKind kind, in Circle circle = default, in Aabb aabb = default, in KDop8 kdop = default, in ConvexPolygon polygon = default, in Segment segment = default)
    {
        Kind = kind;
        _circle = circle;
        _aabb = aabb;
        _kdop = kdop;
        _polygon = polygon;
        _segment = segment;
    }

    /// <summary>Which shape this is.</summary>
    public ShapeKind Kind { get; }

    /// <summary>The outer bounding circle of the shape held.</summary>
    public Circle BoundingCircle => Kind switch
    {
        ShapeKind.Circle => _circle,
        ShapeKind.Aabb => _aabb.BoundingCircle,
        ShapeKind.KDop8 => _kdop.BoundingCircle,
        ShapeKind.Polygon => _polygon.BoundingCircle,
        _ => _segment.BoundingCircle,
    };

    /// <summary>Wraps a circle.</summary>
    /// <param name="circle">The circle.</param>
    public static implicit operator Shape(in Circle circle) => new(ShapeKind.Circle, circle: circle);

    /// <summary>Wraps a box.</summary>
    /// <param name="aabb">The box.</param>
    public static implicit operator Shape(in Aabb aabb) => new(ShapeKind.Aabb, aabb: aabb);

    /// <summary>Wraps an 8-DOP.</summary>
    /// <param name="kdop">The 8-DOP.</param>
    public static implicit operator Shape(in KDop8 kdop) => new(ShapeKind.KDop8, kdop: kdop);

    /// <summary>Wraps a convex polygon.</summary>
    /// <param name="polygon">The polygon.</param>
    public static implicit operator Shape(in ConvexPolygon polygon) => new(ShapeKind.Polygon, polygon: polygon);

    /// <summary>Wraps a segment.</summary>
    /// <param name="segment">The segment.</param>
    public static implicit operator Shape(in Segment segment) => new(ShapeKind.Segment, segment: segment);

    /// <summary>The circle held.</summary>
    /// <returns>The circle.</returns>
    /// <exception cref="InvalidOperationException">The shape is not a circle.</exception>
    public Circle AsCircle() => Kind == ShapeKind.Circle ? _circle : throw WrongKind(ShapeKind.Circle);

    /// <summary>The box held.</summary>
    /// <returns>The box.</returns>
    /// <exception cref="InvalidOperationException">The shape is not a box.</exception>
    public Aabb AsAabb() => Kind == ShapeKind.Aabb ? _aabb : throw WrongKind(ShapeKind.Aabb);

    /// <summary>The 8-DOP held.</summary>
    /// <returns>The 8-DOP.</returns>
    /// <exception cref="InvalidOperationException">The shape is not an 8-DOP.</exception>
    public KDop8 AsKDop8() => Kind == ShapeKind.KDop8 ? _kdop : throw WrongKind(ShapeKind.KDop8);

    /// <summary>The polygon held.</summary>
    /// <returns>The polygon.</returns>
    /// <exception cref="InvalidOperationException">The shape is not a polygon.</exception>
    public ConvexPolygon AsPolygon() => Kind == ShapeKind.Polygon ? _polygon : throw WrongKind(ShapeKind.Polygon);

    /// <summary>The segment held.</summary>
    /// <returns>The segment.</returns>
    /// <exception cref="InvalidOperationException">The shape is not a segment.</exception>
    public Segment AsSegment() => Kind == ShapeKind.Segment ? _segment : throw WrongKind(ShapeKind.Segment);

    [UnscopedRef]
    internal ref readonly Circle CircleRef => ref _circle;

    [UnscopedRef]
    internal ref readonly Aabb AabbRef => ref _aabb;

    [UnscopedRef]
    internal ref readonly KDop8 KDop8Ref => ref _kdop;

    [UnscopedRef]
    internal ref readonly ConvexPolygon PolygonRef => ref _polygon;

    [UnscopedRef]
    internal ref readonly Segment SegmentRef => ref _segment;

    private InvalidOperationException WrongKind(ShapeKind wanted) => new($"the shape is a {Kind}, not a {wanted}");
}
