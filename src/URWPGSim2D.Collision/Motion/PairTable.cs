namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The candidate pairs of the current step, in reusable slots: the pair, its relative travel rate,
/// its sampling interval, the last time it was seen apart, and a generation stamp that changes
/// when the slot is freed (so stale queue entries are ignored). The slots' data is private: the
/// pair schedule (<see cref="PairSchedule"/>) owns the table and the other stages read and write a
/// slot through its methods. Each mover
/// keeps a doubly linked list of its pairs, so that all pairs of a mover are found
/// and removed in time proportional to their number. Slots are reused in a fixed order, so the
/// same events give the same slots. Storage grows by doubling, never shrinks.
/// </summary>
internal sealed class PairTable
{
    private const int None = -1;

    private int[] _moverHead;
    private int[] _edgeNext = new int[128];
    private int[] _edgePrev = new int[128];
    private int[] _moverA = new int[64];
    private int[] _moverB = new int[64];
    private int[] _free = new int[64];
    private int _freeCount;
    private int _used;
    private int _stamp;

    public PairTable(int movers)
    {
        _moverHead = new int[Math.Max(1, movers)];
        Array.Fill(_moverHead, None);
    }

    /// <summary>Follows a new number of movers (empties the table).</summary>
    public void Resize(int movers)
    {
        _moverHead = new int[Math.Max(1, movers)];
        Array.Fill(_moverHead, None);
        Clear();
    }

    private PlannedPair[] _pair = new PlannedPair[64];
    private float[] _rate = new float[64];
    private double[] _interval = new double[64];
    private double[] _lastFree = new double[64];
    private bool[] _apartAtLastFree = new bool[64];
    private int[] _generation = new int[64];
    private int[] _visited = new int[64];
    private bool[] _alive = new bool[64];

    /// <summary>The pair in a slot.</summary>
    public ref readonly PlannedPair Pair(int slot) => ref _pair[slot];

    /// <summary>Most the two bodies of a slot's pair move relative to each other over a whole step, mm.</summary>
    public float Rate(int slot) => _rate[slot];

    /// <summary>A slot's sampling interval, a fraction of the step (a power of two: 1, 1/2, … 1/<see cref="TickQueue.Ticks"/>).</summary>
    public double Interval(int slot) => _interval[slot];

    /// <summary>Last time (fraction of the step) a slot's pair was planned or sampled apart.</summary>
    public double LastFree(int slot) => _lastFree[slot];

    /// <summary>Whether a slot's pair was seen apart at <see cref="LastFree"/> (a pair planned while its bounds overlap was not).</summary>
    public bool ApartAtLastFree(int slot) => _apartAtLastFree[slot];

    /// <summary>A slot's generation: it changes each time the slot is freed.</summary>
    public int Generation(int slot) => _generation[slot];

    /// <summary>Whether a slot holds a pair.</summary>
    public bool IsAlive(int slot) => _alive[slot];

    /// <summary>Whether a slot still holds the pair it held at <paramref name="generation"/> (a queue entry or a held hit is not stale).</summary>
    public bool IsCurrent(int slot, int generation) => _alive[slot] && _generation[slot] == generation;

    /// <summary>Records whether a slot's pair was apart at its last free time.</summary>
    public void SetApartAtLastFree(int slot, bool apart) => _apartAtLastFree[slot] = apart;

    /// <summary>A slot's pair was sampled apart at <paramref name="time"/>.</summary>
    public void MarkFree(int slot, double time)
    {
        _lastFree[slot] = time;
        _apartAtLastFree[slot] = true;
    }

    /// <summary>Marks a slot visited by a pass that took <paramref name="stamp"/> from <see cref="NextStamp"/>; false when it already was.</summary>
    public bool Visit(int slot, int stamp)
    {
        if (_visited[slot] == stamp)
        {
            return false;
        }

        _visited[slot] = stamp;
        return true;
    }

    /// <summary>Slots the storage holds now (it grows by doubling).</summary>
    public int Capacity => _pair.Length;

    /// <summary>Slots ever used since the last <see cref="Clear"/> (alive or free).</summary>
    public int Used => _used;

    /// <summary>A stamp no slot carries yet: a pass marks the slots it has visited with it.</summary>
    public int NextStamp()
    {
        if (++_stamp == int.MaxValue)
        {
            Array.Clear(_visited);
            _stamp = 1;
        }

        return _stamp;
    }

    /// <summary>Frees every slot.</summary>
    public void Clear()
    {
        Array.Fill(_moverHead, None);
        Array.Clear(_alive, 0, _used);
        _used = 0;
        _freeCount = 0;
    }

    /// <summary>
    /// Stores a pair (its movers link it to their lists) with its sampling interval, planned at
    /// <paramref name="plannedAt"/> (its last free time until sampled); returns its slot.
    /// </summary>
    public int Add(in PlannedPair pair, float rate, double interval, double plannedAt)
    {
        int slot = _freeCount > 0 ? _free[--_freeCount] : Grow();
        _pair[slot] = pair;
        _rate[slot] = rate;
        _alive[slot] = true;
        _interval[slot] = interval;
        _lastFree[slot] = plannedAt;
        _moverA[slot] = pair.MoverA;
        _moverB[slot] = pair.MoverB;
        Link(2 * slot, pair.MoverA);
        if (pair.MoverB != None)
        {
            Link((2 * slot) + 1, pair.MoverB);
        }

        return slot;
    }

    /// <summary>The first edge of a mover's list (edge e belongs to slot e / 2), or −1.</summary>
    public int FirstEdge(int mover) => _moverHead[mover];

    /// <summary>The next edge in the same mover's list, or −1.</summary>
    public int NextEdge(int edge) => _edgeNext[edge];

    /// <summary>Frees every pair of a mover (and unlinks it from its partners' lists).</summary>
    public void RemoveAllOf(int mover)
    {
        while (_moverHead[mover] != None)
        {
            Remove(_moverHead[mover] >> 1);
        }
    }

    private void Remove(int slot)
    {
        Unlink(2 * slot, _moverA[slot]);
        if (_moverB[slot] != None)
        {
            Unlink((2 * slot) + 1, _moverB[slot]);
        }

        _alive[slot] = false;
        _generation[slot]++;
        if (_freeCount == _free.Length)
        {
            Array.Resize(ref _free, _free.Length * 2);
        }

        _free[_freeCount++] = slot;
    }

    private void Link(int edge, int mover)
    {
        int head = _moverHead[mover];
        _edgeNext[edge] = head;
        _edgePrev[edge] = None;
        if (head != None)
        {
            _edgePrev[head] = edge;
        }

        _moverHead[mover] = edge;
    }

    private void Unlink(int edge, int mover)
    {
        int prev = _edgePrev[edge], next = _edgeNext[edge];
        if (prev == None)
        {
            _moverHead[mover] = next;
        }
        else
        {
            _edgeNext[prev] = next;
        }

        if (next != None)
        {
            _edgePrev[next] = prev;
        }
    }

    /// <summary>Makes room for at least <paramref name="slots"/> pairs (so a step does not grow the storage).</summary>
    public void Reserve(int slots)
    {
        while (_pair.Length < slots)
        {
            GrowStorage();
        }

        if (_free.Length < slots)
        {
            Array.Resize(ref _free, slots);
        }
    }

    private int Grow()
    {
        if (_used == _pair.Length)
        {
            GrowStorage();
        }

        return _used++;
    }

    private void GrowStorage()
    {
        int size = _pair.Length * 2;
        _pair = Resized(_pair, size);
        _rate = Resized(_rate, size);
        _interval = Resized(_interval, size);
        _lastFree = Resized(_lastFree, size);
        _apartAtLastFree = Resized(_apartAtLastFree, size);
        _generation = Resized(_generation, size);
        _alive = Resized(_alive, size);
        _visited = Resized(_visited, size);
        _moverA = Resized(_moverA, size);
        _moverB = Resized(_moverB, size);
        _edgeNext = Resized(_edgeNext, 2 * size);
        _edgePrev = Resized(_edgePrev, 2 * size);
    }

    private static T[] Resized<T>(T[] array, int size)
    {
        Array.Resize(ref array, size);
        return array;
    }
}
