namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The overlapping pairs one sample found, grouped into clusters that share no moving body (pairs
/// linked through a moving body are one cluster; static bodies and walls link nothing), each with
/// an estimated time of first contact. Buffers grow by doubling and are reused.
/// </summary>
internal sealed class HitClusters
{
    private int[] _order = new int[16];
    private double[] _clusterTime = new double[16];
    private int[] _clusterOf = new int[16];
    private int[] _first = new int[16];
    private int[] _next = new int[16];
    private int _clusters;
    private PairTable? _table;
    private int[] _firstHitOf = [-1, -1, -1, -1, -1, -1, -1, -1];

    /// <summary>Number of hits.</summary>
    public int Count { get; private set; }

    /// <summary>Pair slot of each hit.</summary>
    public int[] Slot { get; private set; } = new int[16];

    /// <summary>The slot's generation when the hit was found.</summary>
    public int[] Generation { get; private set; } = new int[16];

    /// <summary>The contact found.</summary>
    public Hit[] Value { get; private set; } = new Hit[16];

    /// <summary>Estimated time of first contact of each hit.</summary>
    public double[] Estimate { get; private set; } = new double[16];

    /// <summary>Cluster label of each hit (the smallest hit index of its cluster).</summary>
    public int[] Label { get; private set; } = new int[16];

    /// <summary>Makes room for <paramref name="hits"/> hits of a sample among <paramref name="movers"/> movers.</summary>
    public void Reserve(int hits, int movers)
    {
        Size(hits);
        EnsureMovers(Math.Max(0, movers - 1));
    }

    /// <summary>Copies the hits of a sample.</summary>
    public void Load(ReadOnlySpan<int> slots, ReadOnlySpan<Hit> values, int count, PairTable table)
    {
        Size(count);
        Count = count;
        for (int i = 0; i < count; i++)
        {
            Slot[i] = slots[i];
            Generation[i] = table.Generation(slots[i]);
            Value[i] = values[i];
            Label[i] = i;
        }

        _table = table;
    }

    private void Size(int count)
    {
        if (Slot.Length < count)
        {
            int size = Math.Max(count, Slot.Length * 2);
            Slot = new int[size];
            Generation = new int[size];
            Value = new Hit[size];
            Estimate = new double[size];
            Label = new int[size];
            _order = new int[size];
            _clusterTime = new double[size];
            _clusterOf = new int[size];
            _first = new int[size];
            _next = new int[size];
        }
    }

    /// <summary>Labels the clusters: hits that share a moving body, directly or through others, get one label.</summary>
    public void Cluster()
    {
        // Union-find over the hits: each mover remembers the first hit it was seen in.
        for (int i = 0; i < Count; i++)
        {
            Label[i] = i;
        }

        for (int i = 0; i < Count; i++)
        {
            Movers(_table!.Pair(Slot[i]), out int a, out int b);
            Join(i, a);
            if (b >= 0)
            {
                Join(i, b);
            }
        }

        for (int i = 0; i < Count; i++)
        {
            Label[i] = DisjointSets.Root(Label, i);
            Forget(_table!.Pair(Slot[i]));
        }

        // Each cluster (by its root, in ascending order) with its earliest estimate, and its hits
        // chained in ascending order; one pass each.
        _clusters = 0;
        for (int i = 0; i < Count; i++)
        {
            if (Label[i] == i)
            {
                _clusterOf[i] = _clusters;
                _first[i] = -1;
                _order[_clusters] = i;
                _clusterTime[_clusters++] = double.PositiveInfinity;
            }
        }

        for (int k = 0; k < Count; k++)
        {
            int c = _clusterOf[Label[k]];
            _clusterTime[c] = Math.Min(_clusterTime[c], Estimate[k]);
        }

        for (int k = Count - 1; k >= 0; k--)
        {
            int root = Label[k];
            _next[k] = _first[root];
            _first[root] = k;
        }

        // Insertion sort by estimated time (ties: lower label first).
        for (int i = 1; i < _clusters; i++)
        {
            int label = _order[i];
            double time = _clusterTime[i];
            int j = i - 1;
            while (j >= 0 && _clusterTime[j] > time)
            {
                _order[j + 1] = _order[j];
                _clusterTime[j + 1] = _clusterTime[j];
                j--;
            }

            _order[j + 1] = label;
            _clusterTime[j + 1] = time;
        }
    }

    // Links hit i with the first hit that mover m was seen in (the root is always the smallest index).
    private void Join(int i, int mover)
    {
        EnsureMovers(mover);
        int first = _firstHitOf[mover];
        if (first < 0)
        {
            _firstHitOf[mover] = i;
            return;
        }

        DisjointSets.Union(Label, i, first);
    }

    private void Forget(in PlannedPair pair)
    {
        Movers(pair, out int a, out int b);
        _firstHitOf[a] = -1;
        if (b >= 0)
        {
            _firstHitOf[b] = -1;
        }
    }

    private void EnsureMovers(int mover)
    {
        if (mover >= _firstHitOf.Length)
        {
            int old = _firstHitOf.Length;
            Array.Resize(ref _firstHitOf, Math.Max(mover + 1, old * 2));
            Array.Fill(_firstHitOf, -1, old, _firstHitOf.Length - old);
        }
    }

    /// <summary>The cluster labels, earliest estimated contact first.</summary>
    public ReadOnlySpan<int> ClustersByTime() => _order.AsSpan(0, _clusters);

    /// <summary>The first hit (in hit order) of a cluster, by its label from <see cref="ClustersByTime"/>.</summary>
    public int FirstOf(int cluster) => _first[cluster];

    /// <summary>The next hit of the same cluster after hit <paramref name="hit"/>, or −1.</summary>
    public int NextOf(int hit) => _next[hit];

    // The moving bodies of a pair (b = −1 for a static body or the walls).
    private static void Movers(in PlannedPair p, out int a, out int b) => (a, b) = (p.MoverA, p.MoverB);
}
