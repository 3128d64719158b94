namespace URWPGSim2D.Collision;

/// <summary>
/// The exact narrow phase: one <c>Detect(a, b)</c> overload for every ordered pair of the five
/// primitive shapes, plus <see cref="Detect(in Shape, in Shape)"/> for shapes of kinds known
/// only at run time. Every overload follows the conventions of
/// <see cref="CollisionDetectionResult"/> (the MTV moves <c>a</c>; the normal points from
/// <c>b</c> toward <c>a</c>) and allocates nothing.
/// </summary>
public static partial class CollisionDetector
{
    /// <summary>Dispatches to the overload for the two kinds held.</summary>
    /// <param name="a">The shape moved by the MTV.</param>
    /// <param name="b">The other shape.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Shape a, in Shape b) => a.Kind switch
    {
        ShapeKind.Circle => b.Kind switch
        {
            ShapeKind.Circle => Detect(a.CircleRef, b.CircleRef),
            ShapeKind.Aabb => Detect(a.CircleRef, b.AabbRef),
            ShapeKind.KDop8 => Detect(a.CircleRef, b.KDop8Ref),
            ShapeKind.Polygon => Detect(a.CircleRef, b.PolygonRef),
            _ => Detect(a.CircleRef, b.SegmentRef),
        },
        ShapeKind.Aabb => b.Kind switch
        {
            ShapeKind.Circle => Detect(a.AabbRef, b.CircleRef),
            ShapeKind.Aabb => Detect(a.AabbRef, b.AabbRef),
            ShapeKind.KDop8 => Detect(a.AabbRef, b.KDop8Ref),
            ShapeKind.Polygon => Detect(a.AabbRef, b.PolygonRef),
            _ => Detect(a.AabbRef, b.SegmentRef),
        },
        ShapeKind.KDop8 => b.Kind switch
        {
            ShapeKind.Circle => Detect(a.KDop8Ref, b.CircleRef),
            ShapeKind.Aabb => Detect(a.KDop8Ref, b.AabbRef),
            ShapeKind.KDop8 => Detect(a.KDop8Ref, b.KDop8Ref),
            ShapeKind.Polygon => Detect(a.KDop8Ref, b.PolygonRef),
            _ => Detect(a.KDop8Ref, b.SegmentRef),
        },
        ShapeKind.Polygon => b.Kind switch
        {
            ShapeKind.Circle => Detect(a.PolygonRef, b.CircleRef),
            ShapeKind.Aabb => Detect(a.PolygonRef, b.AabbRef),
            ShapeKind.KDop8 => Detect(a.PolygonRef, b.KDop8Ref),
            ShapeKind.Polygon => Detect(a.PolygonRef, b.PolygonRef),
            _ => Detect(a.PolygonRef, b.SegmentRef),
        },
        _ => b.Kind switch
        {
            ShapeKind.Circle => Detect(a.SegmentRef, b.CircleRef),
            ShapeKind.Aabb => Detect(a.SegmentRef, b.AabbRef),
            ShapeKind.KDop8 => Detect(a.SegmentRef, b.KDop8Ref),
            ShapeKind.Polygon => Detect(a.SegmentRef, b.PolygonRef),
            _ => Detect(a.SegmentRef, b.SegmentRef),
        },
    };
}
