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
        pairs.Clear();
        var min = _store.Min;
        var max = _store.Max;
        int n = _store.Count;
        for (int a = 0; a < _store.MovingCount; a++)
        {
            var minA = min[a];
            var maxA = max[a];
            for (int b = a + 1; b < n; b++)
            {
                if (ProxyBox.Overlap(minA, maxA, min[b], max[b]))
                {
                    pairs.Add(a, b);
                }
            }
        }
    }

    /// <inheritdoc/>
    public void Query(in Aabb box, IndexList result)
    {
        ArgumentNullException.ThrowIfNull(result);
        result.Clear();
        var min = _store.Min;
        var max = _store.Max;
        for (int p = 0; p < _store.Count; p++)
        {
            if (ProxyBox.Overlap(box.Min, box.Max, min[p], max[p]))
            {
                result.Add(p);
            }
        }
    }
}
