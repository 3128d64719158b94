using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The other shape of a fish query, as the tree descent needs it: a conservative test against
/// a bounding circle of the fish, its tight slabs on the four 8-DOP axes, and the exact test
/// against one leaf polygon (fish leaf first: the MTV moves the leaf).
/// </summary>
internal interface ILeafPartner
{
    /// <summary>Lower slab values of the partner on the four 8-DOP axes.</summary>
    Vector4 Min { get; }

    /// <summary>Upper slab values of the partner on the four 8-DOP axes.</summary>
    Vector4 Max { get; }

    /// <summary>False only when the partner certainly does not overlap the circle.</summary>
    bool MayOverlap(in Circle bound);

    /// <summary>The exact contact of a leaf (moved by the MTV) with the partner.</summary>
    CollisionDetectionResult Detect(in ConvexView leaf);

    /// <summary>The first half of <see cref="Detect"/>: whether they overlap, and the normal and depth.</summary>
    bool Depth(in ConvexView leaf, out ContactDepth depth);

    /// <summary>The second half: the finished contact for a depth that <see cref="Depth"/> found for this leaf.</summary>
    CollisionDetectionResult Complete(in ConvexView leaf, in ContactDepth depth);
}

/// <summary>Slab helpers shared by the partners and the fish–fish descent.</summary>
internal static class Slabs
{
    /// <summary>Closed-interval overlap on all four axes: false only when some axis strictly separates.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool MayOverlap(Vector4 minA, Vector4 maxA, Vector4 minB, Vector4 maxB) =>
        Vector4.LessThanOrEqualAll(minA, maxB) && Vector4.LessThanOrEqualAll(minB, maxA);

    /// <summary>The exact slabs of a disc: c·aᵢ ± r.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void OfCircle(in Circle c, out Vector4 min, out Vector4 max)
    {
        Vector4 p = KDop8.Project(c.Center);

        // Padded by a few float steps of the coordinates so rounding of p can never make it tighter than the disc.
        var r = new Vector4(c.Radius + 5e-7f * (MathF.Abs(c.Center.X) + MathF.Abs(c.Center.Y)));
        min = p - r;
        max = p + r;
    }

    /// <summary>Closed test of two discs: false only when they are strictly apart.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool MayOverlap(in Circle a, in Circle b)
    {
        float reach = a.Radius + b.Radius;
        return Vector2.DistanceSquared(a.Center, b.Center) <= reach * reach;
    }
}

/// <summary>A circle partner: circle–circle tests on the tree, Voronoi regions at the leaves.</summary>
internal readonly struct CirclePartner : ILeafPartner
{
    private readonly Circle _circle;

    public CirclePartner(in Circle circle)
    {
        _circle = circle;
        Slabs.OfCircle(circle, out Vector4 min, out Vector4 max);
        Min = min;
        Max = max;
    }

    public Vector4 Min { get; }

    public Vector4 Max { get; }

    public bool MayOverlap(in Circle bound) => Slabs.MayOverlap(_circle, bound);

    public CollisionDetectionResult Detect(in ConvexView leaf) => CircleConvex.Detect(_circle, leaf).Swapped();

    // The depth is the circle's (its normal points toward the circle); |MTV| is the same either way.
    public bool Depth(in ConvexView leaf, out ContactDepth depth) => CircleConvex.Depth(_circle, leaf, out depth);

    public CollisionDetectionResult Complete(in ConvexView leaf, in ContactDepth depth) => CircleConvex.Complete(_circle, leaf, depth).Swapped();
}

/// <summary>A polygon-like partner (box, 8-DOP, polygon, segment): slab tests on the tree, SAT at the leaves.</summary>
internal readonly ref struct ConvexPartner : ILeafPartner
{
    private readonly ConvexView _view;

    /// <summary>A partner whose slabs are computed from its vertices (float slabs, padded outward: they only prune).</summary>
    public ConvexPartner(in ConvexView view)
    {
        _view = view;
        FloatSlabs.Of(view.Vertices, out Vector4 min, out Vector4 max);
        Min = min;
        Max = max;
    }

    /// <summary>A partner whose tight slabs are already known.</summary>
    public ConvexPartner(in ConvexView view, Vector4 min, Vector4 max)
    {
        _view = view;
        Min = min;
        Max = max;
    }

    public Vector4 Min { get; }

    public Vector4 Max { get; }

    public bool MayOverlap(in Circle bound)
    {
        Slabs.OfCircle(bound, out Vector4 min, out Vector4 max);
        return Slabs.MayOverlap(min, max, Min, Max);
    }

    public CollisionDetectionResult Detect(in ConvexView leaf) => ConvexSat.Detect(leaf, _view);

    public bool Depth(in ConvexView leaf, out ContactDepth depth) => ConvexSat.Depth(leaf, _view, out depth);

    public CollisionDetectionResult Complete(in ConvexView leaf, in ContactDepth depth) => ConvexSat.Complete(leaf, _view, depth);
}
