namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Queue entries taken out of a <see cref="TickQueue"/> (tick, pair slot, generation), in the
/// order they are added: the entries an island hands from one queue to another. Storage grows by
/// doubling, never shrinks.
/// </summary>
internal sealed class QueueEntries
{
    private int[] _tick = new int[64];
    private int[] _slot = new int[64];
    private int[] _generation = new int[64];

    /// <summary>Number of entries.</summary>
    public int Count { get; private set; }

    /// <summary>Grid tick of each entry (0 … <see cref="TickQueue.Ticks"/>).</summary>
    public ReadOnlySpan<int> Tick => _tick.AsSpan(0, Count);

    /// <summary>Pair slot of each entry.</summary>
    public ReadOnlySpan<int> Slot => _slot.AsSpan(0, Count);

    /// <summary>The generation each entry was scheduled with.</summary>
    public ReadOnlySpan<int> Generation => _generation.AsSpan(0, Count);

    /// <summary>Makes room for at least <paramref name="entries"/> entries.</summary>
    public void Reserve(int entries)
    {
        if (_tick.Length < entries)
        {
            Resize(entries);
        }
    }

    /// <summary>Forgets every entry.</summary>
    public void Clear() => Count = 0;

    /// <summary>Appends one entry.</summary>
    public void Add(int tick, int slot, int generation)
    {
        if (Count == _tick.Length)
        {
            Resize(Count * 2);
        }

        _tick[Count] = tick;
        _slot[Count] = slot;
        _generation[Count++] = generation;
    }

    private void Resize(int size)
    {
        Array.Resize(ref _tick, size);
        Array.Resize(ref _slot, size);
        Array.Resize(ref _generation, size);
    }
}
