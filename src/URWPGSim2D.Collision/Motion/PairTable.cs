using System;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The candidate pairs of the current step, in reusable slots: the pair, its relative travel rate,
/// its sampling interval, the last time it was seen apart, and a generation stamp that changes
/// when the slot is freed (so stale queue entries are ignored). Each mover
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

    /// <summary>The pair in each slot.</summary>
    public PlannedPair[] Pair { get; private set; } = new PlannedPair[64];

    /// <summary>Most the two bodies move relative to each other over a whole step, mm.</summary>
    public float[] Rate { get; private set; } = new float[64];

    /// <summary>Sampling interval, a fraction of the step (a power of two: 1, 1/2, … 1/<see cref="TickQueue.Ticks"/>).</summary>
    public double[] Interval { get; private set; } = new double[64];

    /// <summary>Last time (fraction of the step) the pair was planned or sampled apart.</summary>
    public double[] LastFree { get; private set; } = new double[64];

    /// <summary>Whether the pair was seen apart at <see cref="LastFree"/> (a pair planned while its bounds overlap was not).</summary>
    public bool[] ApartAtLastFree { get; private set; } = new bool[64];

    /// <summary>Changes each time the slot is freed.</summary>
    public int[] Generation { get; private set; } = new int[64];

    /// <summary>A mark per slot for passes over the pairs of several movers (see <see cref="NextStamp"/>).</summary>
    public int[] Stamp { get; private set; } = new int[64];

    /// <summary>Whether the slot holds a pair.</summary>
    public bool[] Alive { get; private set; } = new bool[64];

    /// <summary>Slots ever used since the last <see cref="Clear"/> (alive or free).</summary>
    public int Used => _used;

    /// <summary>A stamp no slot carries yet: a pass marks the slots it has visited with it.</summary>
    public int NextStamp()
    {
        if (++_stamp == int.MaxValue)
        {
            Array.Clear(Stamp);
            _stamp = 1;
        }

        return _stamp;
    }

    /// <summary>Frees every slot.</summary>
    public void Clear()
    {
        Array.Fill(_moverHead, None);
        Array.Clear(Alive, 0, _used);
        _used = 0;
        _freeCount = 0;
    }

    /// <summary>Stores a pair (its movers link it to their lists); returns its slot.</summary>
    public int Add(in PlannedPair pair, float rate)
    {
        int slot = _freeCount > 0 ? _free[--_freeCount] : Grow();
        Pair[slot] = pair;
        Rate[slot] = rate;
        Alive[slot] = true;
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

        Alive[slot] = false;
        Generation[slot]++;
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
        while (Pair.Length < slots)
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
        if (_used == Pair.Length)
        {
            GrowStorage();
        }

        return _used++;
    }

    private void GrowStorage()
    {
        int size = Pair.Length * 2;
        Pair = Resized(Pair, size);
        Rate = Resized(Rate, size);
        Interval = Resized(Interval, size);
        LastFree = Resized(LastFree, size);
        ApartAtLastFree = Resized(ApartAtLastFree, size);
        Generation = Resized(Generation, size);
        Alive = Resized(Alive, size);
        Stamp = Resized(Stamp, size);
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
