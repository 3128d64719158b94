using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision.Fish;

/// <content>
/// Every leaf contact, written into the caller's span (body group leaves first, then the tail
/// group, in <see cref="FishPart"/> order; fish–fish: group pair by group pair). A span of
/// <see cref="MaxContactsWithShape"/> (shape) or <see cref="MaxContactsWithFish"/> (fish)
/// contacts always suffices; a shorter one that fills up throws after writing what fitted.
/// The deepest contact written is the one <c>Detect</c> returns.
/// </content>
public static partial class FishCollision
{
    /// <summary>Every leaf contact of a fish with a circle.</summary>
    /// <param name="a">The fish, moved by each MTV.</param>
    /// <param name="b">The circle.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(FishModel a, in Circle b, Span<FishContact> contacts)
    {
        ArgumentNullException.ThrowIfNull(a);
        var partner = new CirclePartner(b);
        return All(a, ref partner, contacts);
    }

    /// <summary>Every leaf contact of a circle with a fish (each MTV moves the circle).</summary>
    /// <param name="a">The circle, moved by each MTV.</param>
    /// <param name="b">The fish.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(in Circle a, FishModel b, Span<FishContact> contacts) => SwapAll(DetectAll(b, a, contacts), contacts);

    /// <summary>Every leaf contact of a fish with a box.</summary>
    /// <param name="a">The fish, moved by each MTV.</param>
    /// <param name="b">The box.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(FishModel a, in Aabb b, Span<FishContact> contacts)
    {
        ArgumentNullException.ThrowIfNull(a);
        Span<Vector2> corners = stackalloc Vector2[4];
        b.WriteVertices(corners);
        SlabSat.Of(b, out Vector4 min, out Vector4 max);
        var partner = new ConvexPartner(Aabb.View(corners), min, max);
        return All(a, ref partner, contacts);
    }

    /// <summary>Every leaf contact of a box with a fish (each MTV moves the box).</summary>
    /// <param name="a">The box, moved by each MTV.</param>
    /// <param name="b">The fish.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(in Aabb a, FishModel b, Span<FishContact> contacts) => SwapAll(DetectAll(b, a, contacts), contacts);

    /// <summary>Every leaf contact of a fish with an 8-DOP.</summary>
    /// <param name="a">The fish, moved by each MTV.</param>
    /// <param name="b">The 8-DOP.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(FishModel a, in KDop8 b, Span<FishContact> contacts)
    {
        ArgumentNullException.ThrowIfNull(a);
        var partner = new ConvexPartner(b.View(), b.MinSlabs, b.MaxSlabs);
        return All(a, ref partner, contacts);
    }

    /// <summary>Every leaf contact of an 8-DOP with a fish (each MTV moves the 8-DOP).</summary>
    /// <param name="a">The 8-DOP, moved by each MTV.</param>
    /// <param name="b">The fish.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(in KDop8 a, FishModel b, Span<FishContact> contacts) => SwapAll(DetectAll(b, a, contacts), contacts);

    /// <summary>Every leaf contact of a fish with a convex polygon.</summary>
    /// <param name="a">The fish, moved by each MTV.</param>
    /// <param name="b">The polygon.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(FishModel a, in ConvexPolygon b, Span<FishContact> contacts)
    {
        ArgumentNullException.ThrowIfNull(a);
        var partner = new ConvexPartner(b.View());
        return All(a, ref partner, contacts);
    }

    /// <summary>Every leaf contact of a convex polygon with a fish (each MTV moves the polygon).</summary>
    /// <param name="a">The polygon, moved by each MTV.</param>
    /// <param name="b">The fish.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(in ConvexPolygon a, FishModel b, Span<FishContact> contacts) => SwapAll(DetectAll(b, a, contacts), contacts);

    /// <summary>Every leaf contact of a fish with a segment.</summary>
    /// <param name="a">The fish, moved by each MTV.</param>
    /// <param name="b">The segment.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(FishModel a, in Segment b, Span<FishContact> contacts)
    {
        ArgumentNullException.ThrowIfNull(a);
        Span<Vector2> vertices = stackalloc Vector2[2];
        Span<Vector2> normals = stackalloc Vector2[2];
        b.WriteView(vertices, normals);
        var partner = new ConvexPartner(Segment.View(vertices, normals));
        return All(a, ref partner, contacts);
    }

    /// <summary>Every leaf contact of a segment with a fish (each MTV moves the segment).</summary>
    /// <param name="a">The segment, moved by each MTV.</param>
    /// <param name="b">The fish.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(in Segment a, FishModel b, Span<FishContact> contacts) => SwapAll(DetectAll(b, a, contacts), contacts);

    /// <summary>Every leaf-pair contact of two fish.</summary>
    /// <param name="a">The first fish, moved by each MTV.</param>
    /// <param name="b">The second fish.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException">A fish is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(FishModel a, FishModel b, Span<FishContact> contacts)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);
        var sink = new SpanSink(contacts);
        FishTree.Descend(a, b, ref sink);
        return sink.Count;
    }

    /// <summary>Every leaf contact of a fish with a shape of any kind.</summary>
    /// <param name="a">The fish, moved by each MTV.</param>
    /// <param name="b">The shape.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(FishModel a, in Shape b, Span<FishContact> contacts) => b.Kind switch
    {
        ShapeKind.Circle => DetectAll(a, b.CircleRef, contacts),
        ShapeKind.Aabb => DetectAll(a, b.AabbRef, contacts),
        ShapeKind.KDop8 => DetectAll(a, b.KDop8Ref, contacts),
        ShapeKind.Polygon => DetectAll(a, b.PolygonRef, contacts),
        _ => DetectAll(a, b.SegmentRef, contacts),
    };

    /// <summary>Every leaf contact of a shape of any kind with a fish (each MTV moves the shape).</summary>
    /// <param name="a">The shape, moved by each MTV.</param>
    /// <param name="b">The fish.</param>
    /// <param name="contacts">Where to write the contacts.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="contacts"/> is too short for the contacts found.</exception>
    public static int DetectAll(in Shape a, FishModel b, Span<FishContact> contacts) => SwapAll(DetectAll(b, a, contacts), contacts);

    private static int All<TPartner>(FishModel fish, scoped ref TPartner partner, Span<FishContact> contacts)
        where TPartner : ILeafPartner, allows ref struct
    {
        var sink = new SpanSink(contacts);
        FishTree.Descend(fish, ref partner, ref sink);
        return sink.Count;
    }

    private static int SwapAll(int count, Span<FishContact> contacts)
    {
        for (int i = 0; i < count; i++)
        {
            contacts[i] = contacts[i].Swapped();
        }

        return count;
    }
}
