namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Hits held back for the motion world's event loop: each island sampled on its own stops at the first
/// sample that finds a hit and hands its hits over (tick, pair slot, the slot's generation then,
/// the contact), to be handled when the event loop reaches that tick. Storage grows by doubling,
/// never shrinks.
/// </summary>
internal sealed class HeldHits
{
    private int[] _tick = new int[64];
    private int[] _slot = new int[64];
    private int[] _generation = new int[64];
    private Hit[] _hit = new Hit[64];
    private int[]? _perTick; // the counting sort's, made when first needed (a small world never sorts that many)

    /// <summary>Number of hits held.</summary>
    public int Count { get; private set; }

    /// <summary>Grid tick at which each hit was found.</summary>
    public ReadOnlySpan<int> Tick => _tick.AsSpan(0, Count);

    /// <summary>Pair slot of each hit.</summary>
    public ReadOnlySpan<int> Slot => _slot.AsSpan(0, Count);

    /// <summary>The slot's generation when each hit was found (a slot freed since makes the hit stale).</summary>
    public ReadOnlySpan<int> Generation => _generation.AsSpan(0, Count);

    /// <summary>The contact of each hit.</summary>
    public ReadOnlySpan<Hit> Value => _hit.AsSpan(0, Count);

    /// <summary>Makes room for at least <paramref name="hits"/> hits.</summary>
    public void Reserve(int hits)
    {
        if (_tick.Length < hits)
        {
            Resize(hits);
        }
    }

    /// <summary>Forgets every hit.</summary>
    public void Clear() => Count = 0;

    /// <summary>Holds one hit.</summary>
    public void Add(int tick, int slot, int generation, in Hit hit)
    {
        if (Count == _tick.Length)
        {
            Resize(Count * 2);
        }

        _tick[Count] = tick;
        _slot[Count] = slot;
        _generation[Count] = generation;
        _hit[Count++] = hit;
    }

    /// <summary>Appends every hit of <paramref name="other"/>, in its order.</summary>
    public void AddAll(HeldHits other)
    {
        for (int i = 0; i < other.Count; i++)
        {
            Add(other._tick[i], other._slot[i], other._generation[i], other._hit[i]);
        }
    }

    /// <summary>
    /// Puts the hits of <paramref name="from"/> into this set ordered by tick, keeping their order
    /// within a tick: a stable insertion sort for a few hits (a step usually holds a handful), a
    /// stable counting sort over the step's ticks for many. Both give the same order.
    /// </summary>
    public void SortByTick(HeldHits from)
    {
        Clear();
        Reserve(from.Count);
        if (from.Count <= InsertionSortLimit)
        {
            InsertInOrder(from);
            return;
        }

        if (_perTick is null)
        {
            _perTick = new int[TickQueue.Ticks + 2];
        }
        else
        {
            Array.Clear(_perTick);
        }

        for (int i = 0; i < from.Count; i++)
        {
            _perTick[from._tick[i] + 1]++;
        }

        for (int t = 1; t < _perTick.Length; t++)
        {
            _perTick[t] += _perTick[t - 1];
        }

        for (int i = 0; i < from.Count; i++)
        {
            int at = _perTick[from._tick[i]]++;
            _tick[at] = from._tick[i];
            _slot[at] = from._slot[i];
            _generation[at] = from._generation[i];
            _hit[at] = from._hit[i];
        }

        Count = from.Count;
    }

    /// <summary>Most hits sorted by insertion; above it the counting sort's pass over every tick is cheaper.</summary>
    internal const int InsertionSortLimit = 48;

    // Each hit goes in after every held hit of the same or an earlier tick (stable).
    private void InsertInOrder(HeldHits from)
    {
        for (int i = 0; i < from.Count; i++)
        {
            int tick = from._tick[i];
            int at = i;
            while (at > 0 && _tick[at - 1] > tick)
            {
                _tick[at] = _tick[at - 1];
                _slot[at] = _slot[at - 1];
                _generation[at] = _generation[at - 1];
                _hit[at] = _hit[at - 1];
                at--;
            }

            _tick[at] = tick;
            _slot[at] = from._slot[i];
            _generation[at] = from._generation[i];
            _hit[at] = from._hit[i];
        }

        Count = from.Count;
    }

    private void Resize(int size)
    {
        Array.Resize(ref _tick, size);
        Array.Resize(ref _slot, size);
        Array.Resize(ref _generation, size);
        Array.Resize(ref _hit, size);
    }
}
