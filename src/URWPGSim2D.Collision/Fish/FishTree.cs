using URWPGSim2D.Collision.NarrowPhase;
using URWPGSim2D.Collision.Shapes;

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

    /// <summary>Fish against fish: group pairs whose circles may overlap, then leaf pairs whose 8-DOPs may overlap.</summary>
    public static void Descend<TSink>(FishModel a, FishModel b, scoped ref TSink sink)
        where TSink : IContactSink, allows ref struct
    {
        if (!Slabs.MayOverlap(a.Root, b.Root))
        {
            return;
        }

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
                if (Slabs.MayOverlap(circleA, circleB))
                {
                    LeafPairs(a, b, ref sink, ga, gb, circleB);
                }
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

    private static void LeafPairs<TSink>(FishModel a, FishModel b, scoped ref TSink sink, int groupA, int groupB, in Circle circleB)
        where TSink : IContactSink, allows ref struct
    {
        Slabs.OfCircle(circleB, out var circleMin, out var circleMax);
        int firstB = groupB == 0 ? 0 : FishLeafLayout.BodyGroupEnd;
        int endB = groupB == 0 ? FishLeafLayout.BodyGroupEnd : FishLeafLayout.LeafCount;
        int endA = groupA == 0 ? FishLeafLayout.BodyGroupEnd : FishLeafLayout.LeafCount;
        for (int la = groupA == 0 ? 0 : FishLeafLayout.BodyGroupEnd; la < endA; la++)
        {
            var minA = a.LeafMin(la);
            var maxA = a.LeafMax(la);
            if (!Slabs.MayOverlap(minA, maxA, circleMin, circleMax))
            {
                continue;
            }

            for (int lb = firstB; lb < endB; lb++)
            {
                if (!Slabs.MayOverlap(minA, maxA, b.LeafMin(lb), b.LeafMax(lb)))
                {
                    continue;
                }

                if (!sink.TakesDepths)
                {
                    sink.Add(ConvexSat.Detect(a.LeafView(la), b.LeafView(lb)), la, lb);
                }
                else if (ConvexSat.Depth(a.LeafView(la), b.LeafView(lb), out ContactDepth depth))
                {
                    sink.Offer(depth, la, lb);
                }
            }
        }
    }
}
