namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// When each candidate pair is next sampled. Sample times are fractions of the step on the dyadic
/// grid k / <see cref="Ticks"/> (exact in double); a pair sampled every 2⁻ⁿ of the step is sampled at
/// the multiples of 2⁻ⁿ, so a coarse pair's sample times are also a fine pair's. The queue keeps
/// one bucket per grid point. Each tick has a first-in first-out list of slot
/// entries (slot and generation: an entry whose slot was freed or reused since is skipped), and a
/// bit set of the ticks with entries finds the next one. Entries may be added to ticks before the
/// one being processed (a contact rewinds its bodies to the time of first contact). Cleared every
/// step; storage grows by doubling, never shrinks.
/// </summary>
internal sealed class TickQueue
{
    /// <summary>Grid points per step (the finest sampling interval is 1 / Ticks of the step).</summary>
    public const int Ticks = 2048;

    private const int None = -1;

    private readonly int[] _head = new int[Ticks + 1];
    private readonly int[] _tail = new int[Ticks + 1];
    private readonly ulong[] _occupied = new ulong[(Ticks + 64) / 64];
    private Node[] _node = new Node[256];
    private int _count;
    private int _freeNodes = None;
    private int _lowest = Ticks + 1;

    public TickQueue()
    {
        Array.Fill(_head, None);
    }

    /// <summary>Empties every tick.</summary>
    public void Clear()
    {
        // No tick below the lowest known one has entries (an empty queue, once looked at, has none left to clear).
        for (int w = Math.Min(_lowest, Ticks) >> 6; w < _occupied.Length; w++)
        {
            ulong bits = _occupied[w];
            while (bits != 0)
            {
                int tick = (w * 64) + BitOperations.TrailingZeroCount(bits);
                _head[tick] = None;
                bits &= bits - 1;
            }

            _occupied[w] = 0;
        }

        _count = 0;
        _freeNodes = None;
        _lowest = Ticks + 1;
    }

    /// <summary>Makes room for at least <paramref name="entries"/> entries per step.</summary>
    public void Reserve(int entries)
    {
        if (_node.Length < entries)
        {
            Array.Resize(ref _node, entries);
        }
    }

    /// <summary>Schedules slot <paramref name="slot"/> (of generation <paramref name="generation"/>) at grid time <paramref name="time"/> (a multiple of 1 / <see cref="Ticks"/> in (0, 1]).</summary>
    public void Push(double time, int slot, int generation)
    {
        int tick = (int)(time * Ticks);
        int node = _freeNodes;
        if (node != None)
        {
            _freeNodes = _node[node].Next;
        }
        else
        {
            if (_count == _node.Length)
            {
                Array.Resize(ref _node, _count * 2);
            }

            node = _count++;
        }

        _node[node] = new Node(slot, generation, None);
        if (_head[tick] == None)
        {
            _head[tick] = node;
            _occupied[tick >> 6] |= 1UL << (tick & 63);
        }
        else
        {
            _node[_tail[tick]].Next = node;
        }

        _tail[tick] = node;
        _lowest = Math.Min(_lowest, tick);
    }

    /// <summary>The earliest time with entries, or −1 when none is left.</summary>
    public double NextTime()
    {
        int tick = NextTick();
        return tick < 0 ? -1.0 : (double)tick / Ticks;
    }

    /// <summary>Detaches the entries of grid time <paramref name="time"/>; returns the first node (follow <see cref="Next"/>), or −1.</summary>
    public int Take(double time) => Take((int)(time * Ticks));

    private int NextTick()
    {
        for (int w = _lowest >> 6; w < _occupied.Length; w++)
        {
            ulong bits = _occupied[w];
            if (w == _lowest >> 6)
            {
                bits &= ulong.MaxValue << (_lowest & 63);
            }

            if (bits != 0)
            {
                _lowest = (w * 64) + BitOperations.TrailingZeroCount(bits);
                return _lowest;
            }
        }

        _lowest = Ticks + 1;
        return None;
    }

    private int Take(int tick)
    {
        int first = _head[tick];
        _head[tick] = None;
        _occupied[tick >> 6] &= ~(1UL << (tick & 63));
        return first;
    }

    /// <summary>Gives the nodes of a taken chain (from <see cref="Take(double)"/>) back for reuse, once they have been read.</summary>
    public void Recycle(int first)
    {
        while (first != None)
        {
            int next = _node[first].Next;
            _node[first].Next = _freeNodes;
            _freeNodes = first;
            first = next;
        }
    }

    /// <summary>
    /// Moves every entry into <paramref name="into"/>, earliest tick first and in first-in first-out
    /// order within a tick (pushing them back in that order rebuilds the same ticks), and empties the queue.
    /// </summary>
    public void DrainInto(QueueEntries into)
    {
        for (int w = 0; w < _occupied.Length; w++)
        {
            for (ulong bits = _occupied[w]; bits != 0; bits &= bits - 1)
            {
                int tick = (w * 64) + BitOperations.TrailingZeroCount(bits);
                for (int node = _head[tick]; node != None; node = _node[node].Next)
                {
                    into.Add(tick, _node[node].Slot, _node[node].Generation);
                }
            }
        }

        Clear();
    }

    /// <summary>Schedules an entry at a grid tick (0 … <see cref="Ticks"/>), as <see cref="Push"/> does at tick / <see cref="Ticks"/>.</summary>
    public void PushTick(int tick, int slot, int generation) => Push((double)tick / Ticks, slot, generation);

    /// <summary>The slot of a node.</summary>
    public int SlotOf(int node) => _node[node].Slot;

    /// <summary>The generation a node was scheduled with.</summary>
    public int GenerationOf(int node) => _node[node].Generation;

    /// <summary>The node after <paramref name="node"/> in its tick, or −1.</summary>
    public int Next(int node) => _node[node].Next;

    // One entry: the pair's slot, its generation when pushed, the next entry of the same tick (or free list).
    private struct Node(int slot, int generation, int next)
    {
        public int Slot = slot;
        public int Generation = generation;
        public int Next = next;
    }
}
