using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The descent of the fish's bounding-volume tree: root circle, then each group circle, then
/// each leaf 8-DOP, and the exact leaf test only where every bounding volume above it may
/// overlap the partner. All bounding tests are conservative (they prune only what is
/// strictly apart), so the contacts found are exactly those of a test of every leaf. A sink
/// that takes depths gets the first half of each exact test only (see <see cref="DeepestSink"/>).
/// </summary>
internal static class FishTree
{
    /// <summary>Fish against a shape: every leaf contact reaches <paramref name="sink"/>.</summary>
    public static void Descend<TPartner, TSink>(FishModel fish, scoped ref TPartner partner, scoped ref TSink sink)
        where TPartner : ILeafPartner, allows ref struct
        where TSink : IContactSink, allows ref struct
    {
        if (!partner.MayOverlap(fish.Root))
        {
            return;
        }

        if (partner.MayOverlap(fish.BodyGroup))
        {
            Leaves(fish, ref partner, ref sink, 0, FishLeafLayout.BodyGroupEnd);
        }

        if (partner.MayOverlap(fish.TailGroup))
        {
            Leaves(fish, ref partner, ref sink, FishLeafLayout.BodyGroupEnd, FishLeafLayout.LeafCount);
        }
    }

    /// <summary>
    /// Fish against fish: group pairs whose circles may overlap, then leaf pairs whose 8-DOPs may
    /// overlap. A sink of finished results gets them group pair by group pair; a sink of depths
    /// gets the candidates deepest-bound first, and the search stops once no remaining pair can
    /// reach the deepest depth found (see <see cref="DepthBound"/>), which cannot change its answer.
    /// </summary>
    public static void Descend<TSink>(FishModel a, FishModel b, scoped ref TSink sink)
        where TSink : IContactSink, allows ref struct
    {
        var leaves = new ModelLeaves(b);
        DescendFish(a, ref leaves, ref sink);
    }

    /// <summary>Fish against fish, the second given by its circles and leaves (see <see cref="IFishLeaves"/>).</summary>
    public static void DescendFish<TFish, TSink>(FishModel a, scoped ref TFish b, scoped ref TSink sink)
        where TFish : IFishLeaves, allows ref struct
        where TSink : IContactSink, allows ref struct
    {
        if (!Slabs.MayOverlap(a.Root, b.Root))
        {
            return;
        }

        Span<LeafPair> candidates = stackalloc LeafPair[FishLeafLayout.LeafCount * FishLeafLayout.LeafCount];
        int count = 0;
        for (int ga = 0; ga < 2; ga++)
        {
            Circle circleA = ga == 0 ? a.BodyGroup : a.TailGroup;
            if (!Slabs.MayOverlap(circleA, b.Root))
            {
                continue;
            }

            for (int gb = 0; gb < 2; gb++)
            {
                Circle circleB = gb == 0 ? b.BodyGroup : b.TailGroup;
                if (!Slabs.MayOverlap(circleA, circleB))
                {
                    continue;
                }

                // B's group is placed only when some leaf of A's group reaches its circle.
                int nearA = LeavesNear(a, ga, circleB);
                if (nearA != 0)
                {
                    b.Prepare(gb);
                    count = LeafPairs(a, ref b, nearA, gb, candidates, count, sink.TakesDepths);
                }
            }
        }

        if (!sink.TakesDepths)
        {
            foreach (var pair in candidates[..count])
            {
                sink.Add(ConvexSat.Detect(a.LeafView(pair.LeafA), b.LeafView(pair.LeafB)), pair.LeafA, pair.LeafB);
            }

            return;
        }

        DeepestFirst(a, ref b, candidates[..count], ref sink);
    }

    /// <summary>
    /// A bound on the penetration depth of two shapes inside the slabs minA..maxA and
    /// minB..maxB: the least overlap of the slab intervals over the four axes (the depth is the
    /// least overlap of the shapes' projections over all directions, and each projection lies in
    /// its slab), plus a margin for the float round-off of the computed depth.
    /// </summary>
    internal static float DepthBound(Vector4 minA, Vector4 maxA, Vector4 minB, Vector4 maxB)
    {
        Vector4 overlap = Vector4.Min(maxA - minB, maxB - minA);
        float least = MathF.Min(MathF.Min(overlap.X, overlap.Y), MathF.Min(overlap.Z, overlap.W));
        return least + BoundMargin + (BoundRelativeMargin * least);
    }

    // Round-off allowance of a computed depth over the exact one, mm: the narrow phase keeps depths
    // within 0.01 mm of exact at coordinates up to ±25,000 mm; without any allowance the tests
    // find computed depths a few float steps above the slab overlap.
    private const float BoundMargin = 0.05f;

    private const float BoundRelativeMargin = 1e-5f;

    // Candidates by decreasing bound; stop when the next bound is below the deepest depth found.
    private static void DeepestFirst<TFish, TSink>(FishModel a, scoped ref TFish b, scoped Span<LeafPair> candidates, scoped ref TSink sink)
        where TFish : IFishLeaves, allows ref struct
        where TSink : IContactSink, allows ref struct
    {
        for (int i = 1; i < candidates.Length; i++)
        {
            var pair = candidates[i];
            int j = i - 1;
            for (; j >= 0 && candidates[j].Bound < pair.Bound; j--)
            {
                candidates[j + 1] = candidates[j];
            }

            candidates[j + 1] = pair;
        }

        foreach (var pair in candidates)
        {
            if (sink.IsDeeperThan(pair.Bound))
            {
                return;
            }

            if (ConvexSat.Depth(a.LeafView(pair.LeafA), b.LeafView(pair.LeafB), out ContactDepth depth))
            {
                sink.Offer(depth, pair.LeafA, pair.LeafB);
            }
        }
    }

    private static void Leaves<TPartner, TSink>(FishModel fish, scoped ref TPartner partner, scoped ref TSink sink, int first, int end)
        where TPartner : ILeafPartner, allows ref struct
        where TSink : IContactSink, allows ref struct
    {
        for (int leaf = first; leaf < end; leaf++)
        {
            if (!Slabs.MayOverlap(fish.LeafMin(leaf), fish.LeafMax(leaf), partner.Min, partner.Max))
            {
                continue;
            }

            if (!sink.TakesDepths)
            {
                sink.Add(partner.Detect(fish.LeafView(leaf)), leaf, -1);
            }
            else if (partner.Depth(fish.LeafView(leaf), out ContactDepth depth))
            {
                sink.Offer(depth, leaf, -1);
            }
        }
    }

    // The leaves of a's group whose 8-DOPs may overlap the circle, as a bit set (bit i: leaf i).
    private static int LeavesNear(FishModel a, int group, in Circle circle)
    {
        Slabs.OfCircle(circle, out var circleMin, out var circleMax);
        int end = group == 0 ? FishLeafLayout.BodyGroupEnd : FishLeafLayout.LeafCount;
        int near = 0;
        for (int leaf = group == 0 ? 0 : FishLeafLayout.BodyGroupEnd; leaf < end; leaf++)
        {
            if (Slabs.MayOverlap(a.LeafMin(leaf), a.LeafMax(leaf), circleMin, circleMax))
            {
                near |= 1 << leaf;
            }
        }

        return near;
    }

    // The leaf pairs of a's leaves in nearA (a bit set) and b's group groupB whose 8-DOPs overlap, appended at `count` (with depth bounds if asked).
    private static int LeafPairs<TFish>(FishModel a, scoped ref TFish b, int nearA, int groupB, scoped Span<LeafPair> candidates, int count, bool bounds)
        where TFish : IFishLeaves, allows ref struct
    {
        int firstB = groupB == 0 ? 0 : FishLeafLayout.BodyGroupEnd;
        int endB = groupB == 0 ? FishLeafLayout.BodyGroupEnd : FishLeafLayout.LeafCount;
        for (int rest = nearA; rest != 0; rest &= rest - 1)
        {
            int la = BitOperations.TrailingZeroCount(rest);
            var minA = a.LeafMin(la);
            var maxA = a.LeafMax(la);
            for (int lb = firstB; lb < endB; lb++)
            {
                if (Slabs.MayOverlap(minA, maxA, b.LeafMin(lb), b.LeafMax(lb)))
                {
                    candidates[count++] = new LeafPair((byte)la, (byte)lb, bounds ? DepthBound(minA, maxA, b.LeafMin(lb), b.LeafMax(lb)) : 0f);
                }
            }
        }

        return count;
    }

    /// <summary>A leaf pair that passed every bounding volume, and a bound on its depth.</summary>
    private readonly record struct LeafPair(byte LeafA, byte LeafB, float Bound);
}
