namespace URWPGSim2D.Collision.Motion;

/// <summary>A set of mover slots in insertion order, with O(1) membership and clearing in O(size).</summary>
internal sealed class BodySet(int movers)
{
    private readonly bool[] _marks = new bool[Math.Max(1, movers)];
    private readonly int[] _items = new int[Math.Max(1, movers)];

    /// <summary>Number of movers in the set.</summary>
    public int Count { get; private set; }

    /// <summary>The movers, in the order they were added.</summary>
    public ReadOnlySpan<int> Items => _items.AsSpan(0, Count);

    /// <summary>Membership by mover.</summary>
    public ReadOnlySpan<bool> Marks => _marks;

    /// <summary>Adds a mover (no effect if present).</summary>
    public void Add(int mover)
    {
        if (!_marks[mover])
        {
            _marks[mover] = true;
            _items[Count++] = mover;
        }
    }

    /// <summary>Adds the moving bodies of a pair (no effect for those present).</summary>
    public void AddPair(in PlannedPair pair)
    {
        Add(pair.MoverA);
        if (pair.MoverB >= 0)
        {
            Add(pair.MoverB);
        }
    }

    /// <summary>Empties the set.</summary>
    public void Clear()
    {
        for (int i = 0; i < Count; i++)
        {
            _marks[_items[i]] = false;
        }

        Count = 0;
    }
}
