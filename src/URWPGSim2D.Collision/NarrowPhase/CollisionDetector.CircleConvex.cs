using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision;

/// <content>Circle against box, 8-DOP, polygon and segment (and back), all by <see cref="CircleConvex"/>.</content>
public static partial class CollisionDetector
{
    /// <summary>Circle against box by Voronoi regions (see <see cref="Detect(in Circle, in ConvexPolygon)"/>).</summary>
    /// <param name="a">The circle, moved by the MTV.</param>
    /// <param name="b">The box.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Circle a, in Aabb b)
    {
        Span<Vector2> corners = stackalloc Vector2[4];
        b.WriteVertices(corners);
        return CircleConvex.Detect(a, Aabb.View(corners));
    }

    /// <summary>Box against circle: <see cref="Detect(in Circle, in Aabb)"/> swapped.</summary>
    /// <param name="a">The box, moved by the MTV.</param>
    /// <param name="b">The circle.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Aabb a, in Circle b) => Detect(b, a).Swapped();

    /// <summary>Circle against 8-DOP by Voronoi regions over the 8-DOP's vertices.</summary>
    /// <param name="a">The circle, moved by the MTV.</param>
    /// <param name="b">The 8-DOP.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Circle a, in KDop8 b) => CircleConvex.Detect(a, b.View());

    /// <summary>8-DOP against circle: <see cref="Detect(in Circle, in KDop8)"/> swapped.</summary>
    /// <param name="a">The 8-DOP, moved by the MTV.</param>
    /// <param name="b">The circle.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in KDop8 a, in Circle b) => Detect(b, a).Swapped();

    /// <summary>
    /// Circle against convex polygon by Voronoi regions: inside (MTV out through the nearest
    /// edge), edge region (along the edge normal) or vertex region (along centre − vertex).
    /// The action point is the middle of the overlap on the line through the centre along the normal.
    /// </summary>
    /// <param name="a">The circle, moved by the MTV.</param>
    /// <param name="b">The polygon.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Circle a, in ConvexPolygon b) =>
        b.Lanes is { } lanes && PolygonLanes.IsSupported ? CircleLanes.Detect(a, lanes) : CircleConvex.Detect(a, b.View());

    /// <summary>Polygon against circle: <see cref="Detect(in Circle, in ConvexPolygon)"/> swapped.</summary>
    /// <param name="a">The polygon, moved by the MTV.</param>
    /// <param name="b">The circle.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in ConvexPolygon a, in Circle b) => Detect(b, a).Swapped();

    /// <summary>Circle against segment: the segment's edge region or one of its end-point regions.</summary>
    /// <param name="a">The circle, moved by the MTV.</param>
    /// <param name="b">The segment.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Circle a, in Segment b)
    {
        Span<Vector2> vertices = stackalloc Vector2[2];
        Span<Vector2> normals = stackalloc Vector2[2];
        b.WriteView(vertices, normals);
        return CircleConvex.Detect(a, Segment.View(vertices, normals));
    }

    /// <summary>Segment against circle: <see cref="Detect(in Circle, in Segment)"/> swapped.</summary>
    /// <param name="a">The segment, moved by the MTV.</param>
    /// <param name="b">The circle.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Segment a, in Circle b) => Detect(b, a).Swapped();
}
