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
    private Edge[] _edge = new Edge[128];
    private int[] _free = new int[64];
    private int _freeCount;
    private int _used;
    private int _stamp;
    private int _life = 1; // a slot is alive while its Life is this (Clear moves it on instead of touching every slot)

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

    // A slot's data together (what one sample or one re-plan of a pair reads and writes lies on
    // one or two cache lines rather than on one line in each of eight arrays).
    private Slot[] _slot = new Slot[64];

    /// <summary>The pair in a slot.</summary>
    public ref readonly PlannedPair Pair(int slot) => ref _slot[slot].Pair;

    /// <summary>Most the two bodies of a slot's pair move relative to each other over a whole step, mm.</summary>
    public float Rate(int slot) => _slot[slot].Rate;

    /// <summary>A slot's sampling interval, a fraction of the step (a power of two: 1, 1/2, … 1/<see cref="TickQueue.Ticks"/>).</summary>
    public double Interval(int slot) => _slot[slot].Interval;

    /// <summary>Last time (fraction of the step) a slot's pair was planned or sampled apart.</summary>
    public double LastFree(int slot) => _slot[slot].LastFree;

    /// <summary>Whether a slot's pair was seen apart at <see cref="LastFree"/> (a pair planned while its bounds overlap was not).</summary>
    public bool ApartAtLastFree(int slot) => _slot[slot].ApartAtLastFree;

    /// <summary>A slot's generation: it changes each time the slot is freed.</summary>
    public int Generation(int slot) => _slot[slot].Generation;

    /// <summary>Whether a slot holds a pair.</summary>
    public bool IsAlive(int slot) => _slot[slot].Life == _life;

    /// <summary>Whether a slot still holds the pair it held at <paramref name="generation"/> (a queue entry or a held hit is not stale).</summary>
    public bool IsCurrent(int slot, int generation)
    {
        ref readonly Slot s = ref _slot[slot];
        return s.Life == _life && s.Generation == generation;
    }

    /// <summary>Records whether a slot's pair was apart at its last free time.</summary>
    public void SetApartAtLastFree(int slot, bool apart) => _slot[slot].ApartAtLastFree = apart;

    /// <summary>A slot's pair was sampled apart at <paramref name="time"/>.</summary>
    public void MarkFree(int slot, double time)
    {
        ref Slot s = ref _slot[slot];
        s.LastFree = time;
        s.ApartAtLastFree = true;
    }

    /// <summary>Marks a slot visited by a pass that took <paramref name="stamp"/> from <see cref="NextStamp"/>; false when it already was.</summary>
    public bool Visit(int slot, int stamp)
    {
        ref int visited = ref _slot[slot].Visited;
        if (visited == stamp)
        {
            return false;
        }

        visited = stamp;
        return true;
    }

    /// <summary>Slots the storage holds now (it grows by doubling).</summary>
    public int Capacity => _slot.Length;

    /// <summary>Slots ever used since the last <see cref="Clear"/> (alive or free).</summary>
    public int Used => _used;

    /// <summary>A stamp no slot carries yet: a pass marks the slots it has visited with it.</summary>
    public int NextStamp()
    {
        if (++_stamp == int.MaxValue)
        {
            for (int i = 0; i < _slot.Length; i++)
            {
                _slot[i].Visited = 0;
            }

            _stamp = 1;
        }

        return _stamp;
    }

    /// <summary>Frees every slot.</summary>
    public void Clear()
    {
        Array.Fill(_moverHead, None);
        if (++_life == int.MaxValue)
        {
            for (int i = 0; i < _slot.Length; i++)
            {
                _slot[i].Life = 0;
            }

            _life = 1;
        }

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
        ref Slot s = ref _slot[slot];
        s.Pair = pair;
        s.Rate = rate;
        s.Life = _life;
        s.Interval = interval;
        s.LastFree = plannedAt;
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
    public int NextEdge(int edge) => _edge[edge].Next;

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
        ref Slot s = ref _slot[slot];
        Unlink(2 * slot, s.Pair.MoverA);
        if (s.Pair.MoverB != None)
        {
            Unlink((2 * slot) + 1, s.Pair.MoverB);
        }

        s.Life = 0;
        s.Generation++;
        if (_freeCount == _free.Length)
        {
            Array.Resize(ref _free, _free.Length * 2);
        }

        _free[_freeCount++] = slot;
    }

    private void Link(int edge, int mover)
    {
        int head = _moverHead[mover];
        _edge[edge] = new Edge(head, None);
        if (head != None)
        {
            _edge[head].Prev = edge;
        }

        _moverHead[mover] = edge;
    }

    private void Unlink(int edge, int mover)
    {
        (int next, int prev) = (_edge[edge].Next, _edge[edge].Prev);
        if (prev == None)
        {
            _moverHead[mover] = next;
        }
        else
        {
            _edge[prev].Next = next;
        }

        if (next != None)
        {
            _edge[next].Prev = prev;
        }
    }

    /// <summary>Makes room for at least <paramref name="slots"/> pairs (so a step does not grow the storage).</summary>
    public void Reserve(int slots)
    {
        while (_slot.Length < slots)
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
        if (_used == _slot.Length)
        {
            GrowStorage();
        }

        return _used++;
    }

    private void GrowStorage()
    {
        int size = _slot.Length * 2;
        _slot = Resized(_slot, size);
        _edge = Resized(_edge, 2 * size);
    }

    private static T[] Resized<T>(T[] array, int size)
    {
        Array.Resize(ref array, size);
        return array;
    }

    // One slot: the pair, its clock and its bookkeeping.
    private struct Slot
    {
        public PlannedPair Pair;
        public float Rate;
        public double Interval;
        public double LastFree;
        public int Generation;
        public int Visited;
        public int Life;
        public bool ApartAtLastFree;
    }

    // One end of a slot in a mover's list of pairs (edge 2·slot for mover A, 2·slot + 1 for mover B).
    private struct Edge(int next, int prev)
    {
        public int Next = next;
        public int Prev = prev;
    }
}
