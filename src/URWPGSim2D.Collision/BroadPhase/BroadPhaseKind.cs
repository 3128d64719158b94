namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// Which broad phase a <see cref="Motion.MotionWorld"/> finds its candidate pairs with. Every kind
/// finds exactly the same pairs in the same order, so the motion world reports the same contacts, bit
/// for bit, whichever is chosen; they differ only in speed (docs/performance.md).
/// </summary>
public enum BroadPhaseKind
{
    /// <summary>A uniform grid sized from the boxes (the default and the fastest in a match); at most 48 boxes (a match has about 19) are paired by testing every two.</summary>
    UniformGrid,

    /// <summary>Sweep and prune on x: sorted by insertion sort, fastest for about 100 bodies.</summary>
    SweepAndPrune,

    /// <summary>A dynamic AABB tree with fat leaves.</summary>
    DynamicAabbTree,

    /// <summary>Every pair of boxes tested: the reference the others are checked against.</summary>
    BruteForce,
}
