using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Collision queries of a <see cref="FishModel"/> against the primitive shapes and against
/// another fish. Each query descends the fish's bounding-volume tree (root circle, group
/// circles, leaf 8-DOPs) only where the bounding volumes may overlap the partner, and runs the
/// exact test (Voronoi regions for a circle, separating axes otherwise) on the leaf polygons
/// that remain. <c>Detect</c> returns the deepest leaf contact (largest |MTV|; equal depths go
/// to the lower part index); <c>DetectAll</c> writes every leaf contact. The conventions are
/// those of <see cref="CollisionDetectionResult"/>: the MTV moves the first argument. Nothing
/// here allocates.
/// </summary>
public static partial class FishCollision
{
    /// <summary>The most contacts a fish can have with one shape: one per leaf.</summary>
    public const int MaxContactsWithShape = FishLeafLayout.LeafCount;

    /// <summary>The most contacts two fish can have: one per pair of leaves.</summary>
    public const int MaxContactsWithFish = FishLeafLayout.LeafCount * FishLeafLayout.LeafCount;

    /// <summary>Fish against circle: the deepest leaf contact (circle–leaf Voronoi test).</summary>
    /// <param name="a">The fish, moved by the MTV.</param>
    /// <param name="b">The circle.</param>
    /// <returns>The contact with <see cref="FishContact.PartA"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    public static FishContact Detect(FishModel a, in Circle b)
    {
        ArgumentNullException.ThrowIfNull(a);
        if (!Slabs.MayOverlap(a.Root, b))
        {
            return default;
        }

        var partner = new CirclePartner(b);
        return Deepest(a, ref partner);
    }

    /// <summary>Circle against fish: <see cref="Detect(FishModel, in Circle)"/> swapped (MTV moves the circle).</summary>
    /// <param name="a">The circle, moved by the MTV.</param>
    /// <param name="b">The fish.</param>
    /// <returns>The contact with <see cref="FishContact.PartB"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    public static FishContact Detect(in Circle a, FishModel b) => Detect(b, a).Swapped();

    /// <summary>Fish against box: the deepest leaf contact (SAT of each leaf with the box).</summary>
    /// <param name="a">The fish, moved by the MTV.</param>
    /// <param name="b">The box.</param>
    /// <returns>The contact with <see cref="FishContact.PartA"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    public static FishContact Detect(FishModel a, in Aabb b)
    {
        ArgumentNullException.ThrowIfNull(a);
        Span<Vector2> corners = stackalloc Vector2[4];
        b.WriteVertices(corners);
        SlabSat.Of(b, out Vector4 min, out Vector4 max);
        var partner = new ConvexPartner(Aabb.View(corners), min, max);
        return Deepest(a, ref partner);
    }

    /// <summary>Box against fish: <see cref="Detect(FishModel, in Aabb)"/> swapped (MTV moves the box).</summary>
    /// <param name="a">The box, moved by the MTV.</param>
    /// <param name="b">The fish.</param>
    /// <returns>The contact with <see cref="FishContact.PartB"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    public static FishContact Detect(in Aabb a, FishModel b) => Detect(b, a).Swapped();

    /// <summary>Fish against 8-DOP: the deepest leaf contact (SAT of each leaf with the 8-DOP).</summary>
    /// <param name="a">The fish, moved by the MTV.</param>
    /// <param name="b">The 8-DOP.</param>
    /// <returns>The contact with <see cref="FishContact.PartA"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    public static FishContact Detect(FishModel a, in KDop8 b)
    {
        ArgumentNullException.ThrowIfNull(a);
        var partner = new ConvexPartner(b.View(), b.MinSlabs, b.MaxSlabs);
        return Deepest(a, ref partner);
    }

    /// <summary>8-DOP against fish: <see cref="Detect(FishModel, in KDop8)"/> swapped (MTV moves the 8-DOP).</summary>
    /// <param name="a">The 8-DOP, moved by the MTV.</param>
    /// <param name="b">The fish.</param>
    /// <returns>The contact with <see cref="FishContact.PartB"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    public static FishContact Detect(in KDop8 a, FishModel b) => Detect(b, a).Swapped();

    /// <summary>Fish against convex polygon: the deepest leaf contact (SAT of each leaf with the polygon).</summary>
    /// <param name="a">The fish, moved by the MTV.</param>
    /// <param name="b">The polygon.</param>
    /// <returns>The contact with <see cref="FishContact.PartA"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    public static FishContact Detect(FishModel a, in ConvexPolygon b)
    {
        ArgumentNullException.ThrowIfNull(a);
        if (!Slabs.MayOverlap(a.Root, b.BoundingCircle))
        {
            return default;
        }

        var partner = new ConvexPartner(b.View());
        return Deepest(a, ref partner);
    }

    /// <summary>Fish against any convex outline given as a view (vertices and normals in a caller's buffer) with its bounding circle.</summary>
    internal static FishContact Detect(FishModel a, in ConvexView b, in Circle bound)
    {
        if (!Slabs.MayOverlap(a.Root, bound))
        {
            return default;
        }

        var partner = new ConvexPartner(b);
        return Deepest(a, ref partner);
    }

    /// <summary>Convex polygon against fish: <see cref="Detect(FishModel, in ConvexPolygon)"/> swapped (MTV moves the polygon).</summary>
    /// <param name="a">The polygon, moved by the MTV.</param>
    /// <param name="b">The fish.</param>
    /// <returns>The contact with <see cref="FishContact.PartB"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    public static FishContact Detect(in ConvexPolygon a, FishModel b) => Detect(b, a).Swapped();

    /// <summary>Fish against segment: the deepest leaf contact (SAT of each leaf with the segment).</summary>
    /// <param name="a">The fish, moved by the MTV.</param>
    /// <param name="b">The segment.</param>
    /// <returns>The contact with <see cref="FishContact.PartA"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    public static FishContact Detect(FishModel a, in Segment b)
    {
        ArgumentNullException.ThrowIfNull(a);
        Span<Vector2> vertices = stackalloc Vector2[2];
        Span<Vector2> normals = stackalloc Vector2[2];
        b.WriteView(vertices, normals);
        var partner = new ConvexPartner(Segment.View(vertices, normals));
        return Deepest(a, ref partner);
    }

    /// <summary>Segment against fish: <see cref="Detect(FishModel, in Segment)"/> swapped (MTV moves the segment).</summary>
    /// <param name="a">The segment, moved by the MTV.</param>
    /// <param name="b">The fish.</param>
    /// <returns>The contact with <see cref="FishContact.PartB"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    public static FishContact Detect(in Segment a, FishModel b) => Detect(b, a).Swapped();

    /// <summary>
    /// Fish against fish: the deepest contact over the leaf pairs whose group circles and leaf
    /// 8-DOPs overlap (SAT of the two leaf polygons).
    /// </summary>
    /// <param name="a">The first fish, moved by the MTV.</param>
    /// <param name="b">The second fish.</param>
    /// <returns>The contact with both parts set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException">A fish is null.</exception>
    public static FishContact Detect(FishModel a, FishModel b)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);
        var sink = default(DeepestSink);
        FishTree.Descend(a, b, ref sink);
        return sink.Found
            ? FishContact.OfLeaves(ConvexSat.Complete(a.LeafView(sink.LeafA), b.LeafView(sink.LeafB), sink.Best), sink.LeafA, sink.LeafB)
            : FishContact.None;
    }

    /// <summary>
    /// Fish against fish, the second carried into the first one's frame by the rotation (cos, sin) =
    /// <paramref name="rotation"/> and then <paramref name="translation"/> (x ↦ R·x + t), without
    /// rebuilding it: only the leaf groups that come near are moved (see <see cref="FishInFrame"/>).
    /// The contact is in <paramref name="a"/>'s frame.
    /// </summary>
    internal static FishContact Detect(FishModel a, FishModel b, Vector2 rotation, Vector2 translation)
    {
        Span<Vector2> vertices = stackalloc Vector2[FishLeafLayout.VertexCount];
        Span<Vector2> normals = stackalloc Vector2[FishLeafLayout.VertexCount];
        Span<Vector4> min = stackalloc Vector4[FishLeafLayout.LeafCount];
        Span<Vector4> max = stackalloc Vector4[FishLeafLayout.LeafCount];
        var moved = new FishInFrame(b, rotation, translation, vertices, normals, min, max);
        var sink = default(DeepestSink);
        FishTree.DescendFish(a, ref moved, ref sink);
        return sink.Found
            ? FishContact.OfLeaves(ConvexSat.Complete(a.LeafView(sink.LeafA), moved.LeafView(sink.LeafB), sink.Best), sink.LeafA, sink.LeafB)
            : FishContact.None;
    }

    /// <summary>Fish against a shape of any kind: dispatches to the overload for its kind.</summary>
    /// <param name="a">The fish, moved by the MTV.</param>
    /// <param name="b">The shape.</param>
    /// <returns>The contact with <see cref="FishContact.PartA"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    public static FishContact Detect(FishModel a, in Shape b) => b.Kind switch
    {
        ShapeKind.Circle => Detect(a, b.CircleRef),
        ShapeKind.Aabb => Detect(a, b.AabbRef),
        ShapeKind.KDop8 => Detect(a, b.KDop8Ref),
        ShapeKind.Polygon => Detect(a, b.PolygonRef),
        _ => Detect(a, b.SegmentRef),
    };

    /// <summary>A shape of any kind against a fish: <see cref="Detect(FishModel, in Shape)"/> swapped.</summary>
    /// <param name="a">The shape, moved by the MTV.</param>
    /// <param name="b">The fish.</param>
    /// <returns>The contact with <see cref="FishContact.PartB"/> set, or <see cref="FishContact.None"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    public static FishContact Detect(in Shape a, FishModel b) => Detect(b, a).Swapped();

    // Not inlined: the callers' early exits (a root-circle miss) then pay for no stack set-up.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static FishContact Deepest<TPartner>(FishModel fish, scoped ref TPartner partner)
        where TPartner : ILeafPartner, allows ref struct
    {
        var sink = default(DeepestSink);
        FishTree.Descend(fish, ref partner, ref sink);
        return sink.Found
            ? FishContact.OfLeafA(partner.Complete(fish.LeafView(sink.LeafA), sink.Best), sink.LeafA)
            : FishContact.None;
    }
}
