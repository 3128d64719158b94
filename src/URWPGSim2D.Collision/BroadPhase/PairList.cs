namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// A reusable, growable list of <see cref="ProxyPair"/>s that a broad phase fills. It grows by
/// doubling only when a query finds more pairs than ever before, so once warmed up it allocates
/// nothing.
/// </summary>
internal sealed class PairList
{
    private ProxyPair[] _items;

    /// <summary>Creates an empty list with room for <paramref name="capacity"/> pairs.</summary>
    /// <param name="capacity">Initial capacity, ≥ 0.</param>
    /// <exception cref="ArgumentException"><paramref name="capacity"/> is negative.</exception>
    public PairList(int capacity = 64)
    {
        if (capacity < 0)
        {
            throw new ArgumentException($"must be ≥ 0, got {capacity}", nameof(capacity));
        }

        _items = new ProxyPair[capacity];
    }

    /// <summary>Number of pairs.</summary>
    public int Count { get; private set; }

    /// <summary>Pairs the list holds before it grows.</summary>
    public int Capacity => _items.Length;

    /// <summary>The pairs, in the order they were added.</summary>
    public ReadOnlySpan<ProxyPair> Items => _items.AsSpan(0, Count);

    /// <summary>Removes every pair (keeps the storage).</summary>
    public void Clear() => Count = 0;

    /// <summary>Appends a pair.</summary>
    /// <param name="a">The smaller proxy index.</param>
    /// <param name="b">The larger proxy index.</param>
    public void Add(int a, int b)
    {
        if (Count == _items.Length)
        {
            Array.Resize(ref _items, Math.Max(16, _items.Length * 2));
        }

        _items[Count++] = new ProxyPair(a, b);
    }

    /// <summary>Sets the count to <paramref name="count"/> (growing the storage) and returns the pairs to overwrite.</summary>
    internal Span<ProxyPair> Resize(int count)
    {
        if (_items.Length < count)
        {
            Array.Resize(ref _items, Math.Max(count, _items.Length * 2));
        }

        Count = count;
        return _items.AsSpan(0, count);
    }
}
