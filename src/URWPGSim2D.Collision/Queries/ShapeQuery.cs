namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// Queries beside the overlap test of <see cref="CollisionDetector"/>, for every shape kind and
/// the fish: how far apart two shapes are (<see cref="Distance(in Shape, in Shape)"/>), where a ray
/// first enters a shape (<see cref="RayCast(in Shape, Vector2, Vector2)"/>), and when a shape moved
/// along a translation first touches another (<see cref="Cast(in Shape, Vector2, in Shape)"/>).
/// Points and vectors are plane vectors in mm (X = world X, Y = world Z), like the shapes'.
/// Nothing here allocates.
/// </summary>
/// <remarks>
/// Precision: ray casts are exact up to float round-off (edge clipping for polygons, boxes and
/// 8-DOPs, a line crossing for segments, a quadratic for circles). Distances come from a GJK
/// descent that ends on the closest features, so on polygons they are the exact vertex–edge
/// distance up to round-off (about 10⁻⁶ of the shapes' size); the distance from a point to a shape
/// is in closed form (nearest vertex or edge). Casts advance conservatively and stop
/// within <see cref="CastTolerance"/> mm of the contact,
/// never past it. Overlaps are decided by the narrow phase, so touching is not overlapping, as there.
/// </remarks>
public static partial class ShapeQuery
{
    /// <summary>The largest gap, mm, a cast leaves between the shapes at the contact it reports (it never reports a time past the contact).</summary>
    public const float CastTolerance = 1e-3f;

    /// <summary>The distance between two shapes and a closest point on each.</summary>
    /// <param name="a">The first shape.</param>
    /// <param name="b">The second shape.</param>
    /// <returns>The gap (0 when they touch or overlap; then both points are the narrow phase's action point).</returns>
    public static DistanceResult Distance(in Shape a, in Shape b) => Distance(new QueryBody(in a), new QueryBody(in b));

    /// <summary>The distance between two convex polygons (the same as the <see cref="Shape"/> overload, without wrapping them).</summary>
    /// <param name="a">The first polygon.</param>
    /// <param name="b">The second polygon.</param>
    /// <returns>The gap and closest points.</returns>
    public static DistanceResult Distance(in ConvexPolygon a, in ConvexPolygon b)
    {
        float d = Gjk.Distance(QueryShape.Of(a), default, QueryShape.Of(b), out Vector2 pa, out Vector2 pb, out _);
        if (d > 0f)
        {
            return new DistanceResult(d, pa, pb);
        }

        var contact = CollisionDetector.Detect(a, b);
        Vector2 p = contact.Intersect ? XZPlane.ToPlane(contact.ActionPoint) : pa;
        return new DistanceResult(0f, p, p);
    }

    /// <summary>The distance between a fish and a shape: the nearest of its eight leaves.</summary>
    /// <param name="a">The fish.</param>
    /// <param name="b">The shape.</param>
    /// <returns>The gap, closest points and <see cref="DistanceResult.PartA"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    public static DistanceResult Distance(FishModel a, in Shape b)
    {
        ArgumentNullException.ThrowIfNull(a);
        return Distance(new QueryBody(a), new QueryBody(in b));
    }

    /// <summary>The distance between a shape and a fish.</summary>
    /// <param name="a">The shape.</param>
    /// <param name="b">The fish.</param>
    /// <returns>The gap, closest points and <see cref="DistanceResult.PartB"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    public static DistanceResult Distance(in Shape a, FishModel b)
    {
        ArgumentNullException.ThrowIfNull(b);
        return Distance(new QueryBody(in a), new QueryBody(b));
    }

    /// <summary>The distance between two fish: the nearest pair of leaves.</summary>
    /// <param name="a">The first fish.</param>
    /// <param name="b">The second fish.</param>
    /// <returns>The gap, closest points and both parts.</returns>
    /// <exception cref="ArgumentNullException">A fish is null.</exception>
    public static DistanceResult Distance(FishModel a, FishModel b)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);
        return Distance(new QueryBody(a), new QueryBody(b));
    }

    /// <summary>The distance from a point to a shape (0 inside it).</summary>
    /// <param name="shape">The shape.</param>
    /// <param name="point">The point, mm.</param>
    /// <returns>The gap; <see cref="DistanceResult.PointA"/> is the shape's nearest point, <see cref="DistanceResult.PointB"/> the point itself.</returns>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public static DistanceResult Distance(in Shape shape, Vector2 point)
    {
        Guard.Finite(point, nameof(point));
        return ToPoint(new QueryBody(in shape), point);
    }

    /// <summary>The distance from a point to a fish (0 inside a leaf).</summary>
    /// <param name="fish">The fish.</param>
    /// <param name="point">The point, mm.</param>
    /// <returns>The gap; <see cref="DistanceResult.PointA"/> is on the fish's nearest leaf (<see cref="DistanceResult.PartA"/>).</returns>
    /// <exception cref="ArgumentNullException"><paramref name="fish"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public static DistanceResult Distance(FishModel fish, Vector2 point)
    {
        ArgumentNullException.ThrowIfNull(fish);
        Guard.Finite(point, nameof(point));
        return ToPoint(new QueryBody(fish), point);
    }

    internal static DistanceResult Distance(scoped in QueryBody a, scoped in QueryBody b)
    {
        VertexBuffer8 bufferA = default, bufferB = default;
        float best = float.PositiveInfinity;
        Vector2 bestA = default, bestB = default;
        int partA = 0, partB = 0;
        bool bothFish = a.Fish is not null && b.Fish is not null;
        for (int i = 0; i < a.Count; i++)
        {
            var qa = a.Part(i, ref bufferA);
            for (int j = 0; j < b.Count; j++)
            {
                if (bothFish && SlabGap(a.Fish!, i, b.Fish!, j) >= best)
                {
                    continue;
                }

                var qb = b.Part(j, ref bufferB);
                float d = Gjk.Distance(qa, default, qb, out Vector2 pa, out Vector2 pb, out Vector2 separation);
                float gap = d - qa.Radius - qb.Radius;
                if (gap < best)
                {
                    best = gap;
                    partA = i;
                    partB = j;
                    if (d > 0f)
                    {
                        Vector2 n = -separation / d;
                        bestA = pa + (qa.Radius * n);
                        bestB = pb - (qb.Radius * n);
                    }
                    else
                    {
                        bestA = bestB = pa;
                    }
                }
            }
        }

        if (best > 0f)
        {
            return new DistanceResult(best, bestA, bestB, a.PartIndex(partA), b.PartIndex(partB));
        }

        var contact = QueryBody.Contact(a, b);
        if (contact.Intersect)
        {
            Vector2 p = XZPlane.ToPlane(contact.Result.ActionPoint);
            return new DistanceResult(0f, p, p, contact.PartA is { } pa ? (int)pa : -1, contact.PartB is { } pb ? (int)pb : -1);
        }

        Vector2 touch = (bestA + bestB) * 0.5f;
        return new DistanceResult(0f, touch, touch, a.PartIndex(partA), b.PartIndex(partB));
    }

    internal static DistanceResult ToPoint(scoped in QueryBody a, Vector2 point)
    {
        VertexBuffer8 bufferA = default;
        float best = float.PositiveInfinity;
        Vector2 bestA = point;
        int part = 0;
        for (int i = 0; i < a.Count; i++)
        {
            var qa = a.Part(i, ref bufferA);
            float d = PointDistance.ToCore(qa, point, out Vector2 pa);
            float gap = d - qa.Radius;
            if (gap < best)
            {
                best = gap;
                part = i;
                bestA = d > 0f ? pa + ((point - pa) * (qa.Radius / d)) : point;
            }
        }

        return best > 0f
            ? new DistanceResult(best, bestA, point, a.PartIndex(part))
            : new DistanceResult(0f, point, point, a.PartIndex(part));
    }

    // A lower bound of the distance between two fish leaves: the widest gap between their 8-DOP slabs.
    private static float SlabGap(FishModel a, int leafA, FishModel b, int leafB)
    {
        Vector4 gap = Vector4.Max(b.LeafMin(leafB) - a.LeafMax(leafA), a.LeafMin(leafA) - b.LeafMax(leafB));
        return MathF.Max(MathF.Max(gap.X, gap.Y), MathF.Max(gap.Z, gap.W));
    }
}
