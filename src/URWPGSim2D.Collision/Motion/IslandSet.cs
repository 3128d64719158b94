namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The islands of a step: the connected components of the movers under the candidate pairs planned
/// at its start (pairs with a static body or the walls join nothing). Bodies of two islands have
/// swept circles that do not meet, so until a contact response changes a motion, each island is
/// sampled on its own. Islands are numbered by their smallest mover slot; the planned pairs are
/// grouped by island (in slot order within one); the islands are split into contiguous chunks of
/// about equal work. Storage is sized for the world, nothing allocates per step.
/// </summary>
internal sealed class IslandSet
{
    private int[] _parent = [];
    private int[] _number = [];
    private int[] _pairSlot = new int[64];
    private int[] _pairStart = [0];
    private int[] _bodies = [];

    /// <summary>Number of islands (every mover is in one; a mover with no mover partner is an island alone).</summary>
    public int Count { get; private set; }

    /// <summary>The island of each mover.</summary>
    public int[] IslandOf { get; private set; } = [];

    /// <summary>The pair slots, grouped by island.</summary>
    public ReadOnlySpan<int> PairSlot => _pairSlot;

    /// <summary>Island i's pairs are <c>PairSlot[PairStart[i]] … PairSlot[PairStart[i + 1] − 1]</c>.</summary>
    public ReadOnlySpan<int> PairStart => _pairStart.AsSpan(0, Count + 1);

    /// <summary>Sizes the storage for a world of <paramref name="movers"/> movers and up to <paramref name="pairs"/> planned pairs.</summary>
    public void Load(int movers, int pairs)
    {
        _pairSlot = new int[Math.Max(pairs, 64)];
        _parent = new int[movers];
        _number = new int[movers];
        IslandOf = new int[movers];
        _bodies = new int[movers];
        _pairStart = new int[movers + 1];
        Count = 0;
    }

    /// <summary>Finds the islands of the movers under the table's live pairs.</summary>
    public void Build(PairTable table)
    {
        int movers = _parent.Length;
        for (int m = 0; m < movers; m++)
        {
            _parent[m] = m;
        }

        for (int slot = 0; slot < table.Used; slot++)
        {
            if (table.IsAlive(slot) && table.Pair(slot).MoverB >= 0)
            {
                DisjointSets.Union(_parent, table.Pair(slot).MoverA, table.Pair(slot).MoverB);
            }
        }

        Array.Fill(_number, -1);
        Count = 0;
        for (int m = 0; m < movers; m++)
        {
            int root = DisjointSets.Root(_parent, m);
            if (_number[root] < 0)
            {
                _bodies[Count] = 0;
                _number[root] = Count++;
            }

            IslandOf[m] = _number[root];
            _bodies[IslandOf[m]]++;
        }
    }

    /// <summary>Groups the table's pairs by the island of their first mover, in slot order within an island.</summary>
    public void Group(PairTable table)
    {
        int n = table.Used;
        if (_pairSlot.Length < n)
        {
            _pairSlot = new int[Math.Max(n, table.Capacity)];
        }

        Array.Clear(_pairStart, 0, Count + 1);
        for (int slot = 0; slot < n; slot++)
        {
            if (table.IsAlive(slot))
            {
                _pairStart[IslandOf[table.Pair(slot).MoverA] + 1]++;
            }
        }

        for (int i = 1; i <= Count; i++)
        {
            _pairStart[i] += _pairStart[i - 1];
        }

        // Each pair goes to its island's next free position; the starts then move back by one island.
        for (int slot = 0; slot < n; slot++)
        {
            if (table.IsAlive(slot))
            {
                _pairSlot[_pairStart[IslandOf[table.Pair(slot).MoverA]]++] = slot;
            }
        }

        for (int i = Count; i > 0; i--)
        {
            _pairStart[i] = _pairStart[i - 1];
        }

        _pairStart[0] = 0;
    }

    /// <summary>
    /// Splits the islands into at most <paramref name="chunks"/> contiguous ranges of about equal
    /// work (pairs and bodies); range c is <c>starts[c] … starts[c + 1] − 1</c>. Returns the number of ranges.
    /// </summary>
    public int Split(int chunks, Span<int> starts)
    {
        long total = 0;
        for (int i = 0; i < Count; i++)
        {
            total += Work(i);
        }

        int made = 0;
        starts[0] = 0;
        long done = 0;
        for (int i = 0; i < Count && made < chunks - 1; i++)
        {
            done += Work(i);
            if (done * chunks >= total * (made + 1))
            {
                starts[++made] = i + 1;
            }
        }

        starts[++made] = Count;
        return made;
    }

    private long Work(int island) => (2L * (_pairStart[island + 1] - _pairStart[island])) + _bodies[island];
}
