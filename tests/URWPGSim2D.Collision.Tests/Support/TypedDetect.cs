namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>Calls the statically typed <c>CollisionDetector.Detect</c> overload for the kinds held (not the library's own dispatch).</summary>
public static class TypedDetect
{
    /// <summary>The typed overload's answer for a against b.</summary>
    public static CollisionDetectionResult Detect(in Shape a, in Shape b) => a.Kind switch
    {
        ShapeKind.Circle => WithFirst(a.AsCircle(), b),
        ShapeKind.Aabb => WithFirst(a.AsAabb(), b),
        ShapeKind.KDop8 => WithFirst(a.AsKDop8(), b),
        ShapeKind.Polygon => WithFirst(a.AsPolygon(), b),
        _ => WithFirst(a.AsSegment(), b),
    };

    private static CollisionDetectionResult WithFirst(in Circle a, in Shape b) => b.Kind switch
    {
        ShapeKind.Circle => CollisionDetector.Detect(a, b.AsCircle()),
        ShapeKind.Aabb => CollisionDetector.Detect(a, b.AsAabb()),
        ShapeKind.KDop8 => CollisionDetector.Detect(a, b.AsKDop8()),
        ShapeKind.Polygon => CollisionDetector.Detect(a, b.AsPolygon()),
        _ => CollisionDetector.Detect(a, b.AsSegment()),
    };

    private static CollisionDetectionResult WithFirst(in Aabb a, in Shape b) => b.Kind switch
    {
        ShapeKind.Circle => CollisionDetector.Detect(a, b.AsCircle()),
        ShapeKind.Aabb => CollisionDetector.Detect(a, b.AsAabb()),
        ShapeKind.KDop8 => CollisionDetector.Detect(a, b.AsKDop8()),
        ShapeKind.Polygon => CollisionDetector.Detect(a, b.AsPolygon()),
        _ => CollisionDetector.Detect(a, b.AsSegment()),
    };

    private static CollisionDetectionResult WithFirst(in KDop8 a, in Shape b) => b.Kind switch
    {
        ShapeKind.Circle => CollisionDetector.Detect(a, b.AsCircle()),
        ShapeKind.Aabb => CollisionDetector.Detect(a, b.AsAabb()),
        ShapeKind.KDop8 => CollisionDetector.Detect(a, b.AsKDop8()),
        ShapeKind.Polygon => CollisionDetector.Detect(a, b.AsPolygon()),
        _ => CollisionDetector.Detect(a, b.AsSegment()),
    };

    private static CollisionDetectionResult WithFirst(in ConvexPolygon a, in Shape b) => b.Kind switch
    {
        ShapeKind.Circle => CollisionDetector.Detect(a, b.AsCircle()),
        ShapeKind.Aabb => CollisionDetector.Detect(a, b.AsAabb()),
        ShapeKind.KDop8 => CollisionDetector.Detect(a, b.AsKDop8()),
        ShapeKind.Polygon => CollisionDetector.Detect(a, b.AsPolygon()),
        _ => CollisionDetector.Detect(a, b.AsSegment()),
    };

    private static CollisionDetectionResult WithFirst(in Segment a, in Shape b) => b.Kind switch
    {
        ShapeKind.Circle => CollisionDetector.Detect(a, b.AsCircle()),
        ShapeKind.Aabb => CollisionDetector.Detect(a, b.AsAabb()),
        ShapeKind.KDop8 => CollisionDetector.Detect(a, b.AsKDop8()),
        ShapeKind.Polygon => CollisionDetector.Detect(a, b.AsPolygon()),
        _ => CollisionDetector.Detect(a, b.AsSegment()),
    };
}
