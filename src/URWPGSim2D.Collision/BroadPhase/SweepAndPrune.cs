namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// Sweep and prune on the x axis. The proxies are kept sorted by the left edge of their box; the
/// order is repaired by insertion sort before each query, which is nearly linear when the boxes
/// moved little since the last one (temporal coherence). <see cref="FindPairs"/> sweeps the sorted
/// list: each proxy is tested against the following ones until their left edge passes its right
/// edge, and the x-overlapping pairs are then tested on z. The pairs are finally put in the common
/// order (counting sort by the smaller index, insertion sort within). With n objects of similar size
/// spread over a square area, about n^1.5 pairs overlap on x alone, so its cost grows faster
/// than linearly.
/// </summary>
internal sealed class SweepAndPrune : IBroadPhase
{
    private readonly ProxyStore _store = new();
    private int[] _order = new int[16];
    private readonly PairSorter _sorter = new();
    private float _widest;
    private bool _dirty;

    /// <inheritdoc/>
    public int Count => _store.Count;

    /// <inheritdoc/>
    public int MovingCount => _store.MovingCount;

    /// <inheritdoc/>
    public void Reset(ReadOnlySpan<Aabb> boxes, int movingCount)
    {
        int previous = _store.Count;
        _store.Reset(boxes, movingCount);
        int n = _store.Count;
        if (_order.Length < n)
        {
            Array.Resize(ref _order, Math.Max(n, _order.Length * 2));
        }

        if (previous != n)
        {
            for (int i = 0; i < n; i++)
            {
                _order[i] = i;
            }
        }

        _dirty = true;
    }

    /// <inheritdoc/>
    public void Move(int proxy, in Aabb box)
    {
        _store.Move(proxy, box);
        _dirty = true;
    }

    /// <inheritdoc/>
    public Aabb Box(int proxy) => _store.Box(proxy);

    /// <inheritdoc/>
    public void FindPairs(PairList pairs)
    {
        ArgumentNullException.ThrowIfNull(pairs);
        Repair();
        pairs.Clear();
        var min = _store.Min;
        var max = _store.Max;
        int n = _store.Count;
        _sorter.Clear();
        _sorter.Reserve(pairs.Capacity);
        for (int i = 0; i < n; i++)
        {
            int a = _order[i];
            Vector2 minA = min[a], maxA = max[a];
            for (int j = i + 1; j < n; j++)
            {
                int b = _order[j];
                if (min[b].X > maxA.X)
                {
                    break;
                }

                if (minA.Y <= max[b].Y && min[b].Y <= maxA.Y && _store.Pairable(a, b))
                {
                    _sorter.Add(Math.Min(a, b), Math.Max(a, b));
                }
            }
        }

        _sorter.SortInto(n, pairs);
    }

    /// <inheritdoc/>
    public void Query(in Aabb box, IndexList result)
    {
        ArgumentNullException.ThrowIfNull(result);
        Repair();
        result.Clear();
        var min = _store.Min;
        var max = _store.Max;
        int n = _store.Count;

        // Candidates have a left edge in [box.Min.X − widest, box.Max.X]: binary search the start.
        float from = box.Min.X - _widest;
        int lo = 0, hi = n;
        while (lo < hi)
        {
            int mid = (lo + hi) >>> 1;
            if (min[_order[mid]].X < from)
            {
                lo = mid + 1;
            }
            else
            {
                hi = mid;
            }
        }

        for (int i = lo; i < n; i++)
        {
            int p = _order[i];
            if (min[p].X > box.Max.X)
            {
                break;
            }

            if (ProxyBox.Overlap(box.Min, box.Max, min[p], max[p]))
            {
                result.Add(p);
            }
        }

        result.SortFrom(0);
    }

    // Insertion sort of the order by left edge (stable, nearly linear when little moved); widest box.
    private void Repair()
    {
        if (!_dirty)
        {
            return;
        }

        var min = _store.Min;
        var max = _store.Max;
        int n = _store.Count;
        float widest = 0f;
        for (int i = 0; i < n; i++)
        {
            int p = _order[i];
            float key = min[p].X;
            widest = MathF.Max(widest, max[p].X - key);
            int j = i - 1;
            while (j >= 0 && min[_order[j]].X > key)
            {
                _order[j + 1] = _order[j];
                j--;
            }

            _order[j + 1] = p;
        }

        _widest = widest;
        _dirty = false;
    }
}
