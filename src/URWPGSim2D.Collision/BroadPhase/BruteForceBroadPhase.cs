namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// The reference broad phase: every pair of proxies is tested, n·(n − 1)/2 box tests per
/// <see cref="FindPairs"/>. Exact by construction; the others are tested against it.
/// </summary>
internal sealed class BruteForceBroadPhase : IBroadPhase
{
    private readonly ProxyStore _store = new();

    /// <inheritdoc/>
    public int Count => _store.Count;

    /// <inheritdoc/>
    public int MovingCount => _store.MovingCount;

    /// <inheritdoc/>
    public void Reset(ReadOnlySpan<Aabb> boxes, int movingCount) => _store.Reset(boxes, movingCount);

    /// <inheritdoc/>
    public void Move(int proxy, in Aabb box) => _store.Move(proxy, box);

    /// <inheritdoc/>
    public Aabb Box(int proxy) => _store.Box(proxy);

    /// <inheritdoc/>
    public void FindPairs(PairList pairs)
    {
        ArgumentNullException.ThrowIfNull(pairs);
        _store.PairEveryTwo(pairs);
    }

    /// <inheritdoc/>
    public void Query(in Aabb box, IndexList result)
    {
        ArgumentNullException.ThrowIfNull(result);
        result.Clear();
        _store.AddOverlapping(box.Min, box.Max, result);
    }
}
