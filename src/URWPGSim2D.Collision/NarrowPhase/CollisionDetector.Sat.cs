using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision;

/// <content>Every pair of polygon-like shapes with a general edge set, by <see cref="ConvexSat"/>.</content>
public static partial class CollisionDetector
{
    /// <summary>
    /// Convex polygon against convex polygon: separating-axis test over both edge-normal sets,
    /// MTV along the axis of least overlap (exact depth, containment included); the action point
    /// is the area centroid of the intersection polygon.
    /// </summary>
    /// <param name="a">The polygon moved by the MTV.</param>
    /// <param name="b">The other polygon.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in ConvexPolygon a, in ConvexPolygon b) =>
        a.Lanes is not null && b.Lanes is not null && PolygonLanes.IsSupported
            ? ConvexSatWide.Detect(a, b)
            : ConvexSat.Detect(a.View(), b.View());

    /// <summary>Box against polygon: SAT over the box's two axes and the polygon's normals.</summary>
    /// <param name="a">The box, moved by the MTV.</param>
    /// <param name="b">The polygon.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Aabb a, in ConvexPolygon b)
    {
        Span<Vector2> corners = stackalloc Vector2[4];
        a.WriteVertices(corners);
        return ConvexSat.Detect(Aabb.View(corners), b.View());
    }

    /// <summary>Polygon against box: <see cref="Detect(in Aabb, in ConvexPolygon)"/> swapped.</summary>
    /// <param name="a">The polygon, moved by the MTV.</param>
    /// <param name="b">The box.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in ConvexPolygon a, in Aabb b) => Detect(b, a).Swapped();

    /// <summary>8-DOP against polygon: SAT over the four fixed axes and the polygon's normals.</summary>
    /// <param name="a">The 8-DOP, moved by the MTV.</param>
    /// <param name="b">The polygon.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in KDop8 a, in ConvexPolygon b) => ConvexSat.Detect(a.View(), b.View());

    /// <summary>Polygon against 8-DOP: <see cref="Detect(in KDop8, in ConvexPolygon)"/> swapped.</summary>
    /// <param name="a">The polygon, moved by the MTV.</param>
    /// <param name="b">The 8-DOP.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in ConvexPolygon a, in KDop8 b) => Detect(b, a).Swapped();

    /// <summary>Polygon against segment: SAT over the polygon's normals and the segment's normal.</summary>
    /// <param name="a">The polygon, moved by the MTV.</param>
    /// <param name="b">The segment.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in ConvexPolygon a, in Segment b)
    {
        Span<Vector2> vertices = stackalloc Vector2[2];
        Span<Vector2> normals = stackalloc Vector2[2];
        b.WriteView(vertices, normals);
        return ConvexSat.Detect(a.View(), Segment.View(vertices, normals));
    }

    /// <summary>Segment against polygon: <see cref="Detect(in ConvexPolygon, in Segment)"/> swapped.</summary>
    /// <param name="a">The segment, moved by the MTV.</param>
    /// <param name="b">The polygon.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Segment a, in ConvexPolygon b) => Detect(b, a).Swapped();

    /// <summary>Box against segment: SAT over the box's axes and the segment's normal.</summary>
    /// <param name="a">The box, moved by the MTV.</param>
    /// <param name="b">The segment.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Aabb a, in Segment b)
    {
        Span<Vector2> corners = stackalloc Vector2[4];
        a.WriteVertices(corners);
        Span<Vector2> vertices = stackalloc Vector2[2];
        Span<Vector2> normals = stackalloc Vector2[2];
        b.WriteView(vertices, normals);
        return ConvexSat.Detect(Aabb.View(corners), Segment.View(vertices, normals));
    }

    /// <summary>Segment against box: <see cref="Detect(in Aabb, in Segment)"/> swapped.</summary>
    /// <param name="a">The segment, moved by the MTV.</param>
    /// <param name="b">The box.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Segment a, in Aabb b) => Detect(b, a).Swapped();

    /// <summary>8-DOP against segment: SAT over the four fixed axes and the segment's normal.</summary>
    /// <param name="a">The 8-DOP, moved by the MTV.</param>
    /// <param name="b">The segment.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in KDop8 a, in Segment b)
    {
        Span<Vector2> vertices = stackalloc Vector2[2];
        Span<Vector2> normals = stackalloc Vector2[2];
        b.WriteView(vertices, normals);
        return ConvexSat.Detect(a.View(), Segment.View(vertices, normals));
    }

    /// <summary>Segment against 8-DOP: <see cref="Detect(in KDop8, in Segment)"/> swapped.</summary>
    /// <param name="a">The segment, moved by the MTV.</param>
    /// <param name="b">The 8-DOP.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Segment a, in KDop8 b) => Detect(b, a).Swapped();

    /// <summary>
    /// Segment against segment (two flat shapes): they overlap only where they cross; the MTV is
    /// the shorter push along either segment's normal and the action point is the crossing.
    /// </summary>
    /// <param name="a">The segment moved by the MTV.</param>
    /// <param name="b">The other segment.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Segment a, in Segment b)
    {
        Span<Vector2> va = stackalloc Vector2[2];
        Span<Vector2> na = stackalloc Vector2[2];
        Span<Vector2> vb = stackalloc Vector2[2];
        Span<Vector2> nb = stackalloc Vector2[2];
        a.WriteView(va, na);
        b.WriteView(vb, nb);
        return ConvexSat.Detect(Segment.View(va, na), Segment.View(vb, nb));
    }
}
