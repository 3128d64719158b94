namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>Creates the broad phase a <see cref="BroadPhaseKind"/> names.</summary>
internal static class BroadPhaseFactory
{
    /// <summary>A new, empty broad phase of the given kind.</summary>
    /// <param name="kind">The kind.</param>
    /// <param name="name">The caller's parameter name, for the error.</param>
    /// <exception cref="ArgumentException"><paramref name="kind"/> is not a defined kind.</exception>
    public static IBroadPhase Create(BroadPhaseKind kind, string name) => kind switch
    {
        BroadPhaseKind.UniformGrid => new UniformGrid(),
        BroadPhaseKind.SweepAndPrune => new SweepAndPrune(),
        BroadPhaseKind.DynamicAabbTree => new DynamicAabbTree(),
        BroadPhaseKind.BruteForce => new BruteForceBroadPhase(),
        _ => throw new ArgumentException($"must be a defined BroadPhaseKind, got {(int)kind}", name),
    };
}
