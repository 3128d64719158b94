namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// A reusable, growable list of proxy indices (the answer of <see cref="IBroadPhase.Query"/>). It
/// grows by doubling only when needed, so once warmed up it allocates nothing.
/// </summary>
internal sealed class IndexList
{
    private int[] _items;

    /// <summary>Creates an empty list with room for <paramref name="capacity"/> indices.</summary>
    /// <param name="capacity">Initial capacity, ≥ 0.</param>
    /// <exception cref="ArgumentException"><paramref name="capacity"/> is negative.</exception>
    public IndexList(int capacity = 64)
    {
        if (capacity < 0)
        {
            throw new ArgumentException($"must be ≥ 0, got {capacity}", nameof(capacity));
        }

        _items = new int[capacity];
    }

    /// <summary>Number of indices.</summary>
    public int Count { get; private set; }

    /// <summary>The indices.</summary>
    public ReadOnlySpan<int> Items => _items.AsSpan(0, Count);

    /// <summary>Removes every index (keeps the storage).</summary>
    public void Clear() => Count = 0;

    /// <summary>Appends an index.</summary>
    /// <param name="index">A proxy index.</param>
    public void Add(int index)
    {
        if (Count == _items.Length)
        {
            Array.Resize(ref _items, Math.Max(16, _items.Length * 2));
        }

        _items[Count++] = index;
    }

    /// <summary>Sorts the indices ascending (insertion sort: the lists are short and often nearly sorted).</summary>
    internal void SortFrom(int start) => InsertionSort(_items.AsSpan(start, Count - start));

    /// <summary>Sorts a short span ascending in place.</summary>
    internal static void InsertionSort(Span<int> items)
    {
        if (items.Length > 32)
        {
            items.Sort();
            return;
        }

        for (int i = 1; i < items.Length; i++)
        {
            int v = items[i];
            int j = i - 1;
            while (j >= 0 && items[j] > v)
            {
                items[j + 1] = items[j];
                j--;
            }

            items[j + 1] = v;
        }
    }
}
