namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The hits of one contact event (a cluster of a sample's hits sharing moving bodies): each pair's
/// slot and the contact the sample found. The contact events own one; the search for the time of
/// first contact reads it. Storage grows by doubling, never shrinks.
/// </summary>
internal sealed class EventHits
{
    private int[] _slot = new int[64];
    private Hit[] _hit = new Hit[64];

    /// <summary>Number of hits.</summary>
    public int Count { get; private set; }

    /// <summary>Pair slot of each hit.</summary>
    public ReadOnlySpan<int> Slot => _slot.AsSpan(0, Count);

    /// <summary>The contact of each hit.</summary>
    public ReadOnlySpan<Hit> Value => _hit.AsSpan(0, Count);

    /// <summary>Makes room for at least <paramref name="hits"/> hits.</summary>
    public void Reserve(int hits)
    {
        if (_slot.Length < hits)
        {
            Array.Resize(ref _slot, hits);
            Array.Resize(ref _hit, hits);
        }
    }

    /// <summary>Forgets every hit.</summary>
    public void Clear() => Count = 0;

    /// <summary>Adds a hit.</summary>
    public void Add(int slot, in Hit hit)
    {
        if (Count == _slot.Length)
        {
            Reserve(Count * 2);
        }

        _slot[Count] = slot;
        _hit[Count++] = hit;
    }
}
