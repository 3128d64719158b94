namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The contacts that persist: one record per pair of bodies that touches, kept across sample times
/// and steps, keyed by the two bodies. A pair touches from its first response (the handler's
/// answer to a contact) until a whole step passes without one; its record holds when it was last
/// answered. The contact events stage
/// asks whether a pair is <em>pressing</em> (answered at one of its last two samples), and the
/// motion world reports touches that begin and end to the handler. An open-addressing table
/// (linear probing, deletion by backward shift; a bitmap of the used slots ends probes and lets
/// the end of a step visit only the touches, since the table is sized for the worst case and is
/// mostly empty) that grows by doubling and never shrinks; after
/// warm-up nothing allocates. Written only by the event loop's thread.
/// </summary>
internal sealed class ContactCache
{
    private const int SmallestSize = 64;

    private Entry[] _entries = new Entry[SmallestSize];
    private ulong[] _used = new ulong[SmallestSize / 64]; // one bit a slot: the slot holds an entry (a slot without it is never read)
    private int _mask = SmallestSize - 1;

    /// <summary>Steps begun since the motion world was made (a touch's time is this plus the time within the step).</summary>
    public long Step { get; private set; }

    /// <summary>Pairs touching now.</summary>
    public int Count { get; private set; }

    /// <summary>Makes room for <paramref name="touches"/> pairs touching at once (the table at most half full).</summary>
    public void Reserve(int touches)
    {
        int size = (int)Math.Max(SmallestSize, BitOperations.RoundUpToPowerOf2((uint)Math.Max(1, 2 * touches)));
        if (size > _entries.Length)
        {
            Rehash(size);
        }
    }

    /// <summary>Forgets every touch (the bodies were removed); ends no touch.</summary>
    public void Clear()
    {
        Array.Clear(_used);
        Count = 0;
    }

    /// <summary>A new step begins.</summary>
    public void BeginStep() => Step++;

    /// <summary>
    /// Records a response to the pair at <paramref name="time"/> of the current step; returns true
    /// when this begins its touch (the pair was not touching).
    /// </summary>
    public bool Touch(int a, int b, double time)
    {
        (int lo, int hi) = Ordered(a, b);
        int i = Find(lo, hi);
        bool began = i < 0;
        if (began)
        {
            if (2 * (Count + 1) > _entries.Length)
            {
                Rehash(_entries.Length * 2);
            }

            i = FreeSlot(lo, hi);
            Mark(i);
            ref Entry fresh = ref _entries[i];
            fresh.Low = lo;
            fresh.High = hi;
            fresh.LowFirst = a == lo;
            Count++;
        }

        ref Entry e = ref _entries[i];
        e.LastStep = Step;
        e.LastTime = time;
        return began;
    }

    /// <summary>
    /// Whether the pair is pressing at <paramref name="time"/> of the current step: it touches and
    /// was answered no longer ago than <paramref name="window"/> (a fraction of a step; across the
    /// start of the step too).
    /// </summary>
    public bool IsPressing(int a, int b, double time, double window)
    {
        (int lo, int hi) = Ordered(a, b);
        int i = Find(lo, hi);
        if (i < 0)
        {
            return false;
        }

        ref readonly Entry e = ref _entries[i];
        double since = ((Step - e.LastStep) + time) - e.LastTime;
        return since <= window;
    }

    /// <summary>Whether the pair touches now.</summary>
    public bool IsTouching(int a, int b)
    {
        (int lo, int hi) = Ordered(a, b);
        return Find(lo, hi) >= 0;
    }

    /// <summary>
    /// The end of a step: the touches without a response in this step end. Each ended pair is
    /// passed to <paramref name="ended"/> in the order of the contact that began its touch, in the
    /// table's order, then removed; returns how many ended.
    /// </summary>
    public int EndStep<TSink>(ref TSink ended)
        where TSink : struct, IEndedSink
    {
        // The used slots in slot order, found from the bitmap: in a crowd the table is mostly empty.
        int count = 0;
        for (int i = 0; Count > 0 && (i = NextUsed(i)) >= 0;)
        {
            ref Entry e = ref _entries[i];
            if (Step - e.LastStep >= 1)
            {
                ended.Ended(e.LowFirst ? e.Low : e.High, e.LowFirst ? e.High : e.Low);
                Remove(i);
                count++;
                continue; // the backward shift may have moved another entry into this slot
            }

            i++;
        }

        return count;
    }

    // Index of the pair's entry, or −1.
    private int Find(int lo, int hi)
    {
        for (int i = Home(lo, hi); ; i = (i + 1) & _mask)
        {
            // The bitmap ends a probe without reading the (mostly empty, large) table.
            if (!IsUsed(i))
            {
                return -1;
            }

            ref readonly Entry e = ref _entries[i];
            if (e.Low == lo && e.High == hi)
            {
                return i;
            }
        }
    }

    private int FreeSlot(int lo, int hi)
    {
        int i = Home(lo, hi);
        while (IsUsed(i))
        {
            i = (i + 1) & _mask;
        }

        return i;
    }

    // Deletion by backward shift: later entries of the probe run move back so every entry stays reachable.
    private void Remove(int hole)
    {
        int i = hole;
        while (true)
        {
            i = (i + 1) & _mask;
            if (!IsUsed(i))
            {
                break;
            }

            ref Entry e = ref _entries[i];

            int home = Home(e.Low, e.High);
            bool movable = hole <= i ? (home <= hole || home > i) : (home <= hole && home > i);
            if (movable)
            {
                _entries[hole] = e;
                Mark(hole);
                hole = i;
            }
        }

        _used[hole >> 6] &= ~(1UL << hole);
        Count--;
    }

    private void Rehash(int size)
    {
        Entry[] old = _entries;
        ulong[] oldUsed = _used;
        _entries = new Entry[size];
        _used = new ulong[Math.Max(1, size / 64)];
        _mask = size - 1;
        for (int j = 0; j < old.Length; j++)
        {
            if (IsUsed(oldUsed, j))
            {
                ref readonly Entry e = ref old[j];
                int i = FreeSlot(e.Low, e.High);
                _entries[i] = e;
                Mark(i);
            }
        }
    }

    private bool IsUsed(int slot) => IsUsed(_used, slot);

    private static bool IsUsed(ulong[] used, int slot) => (used[slot >> 6] & (1UL << slot)) != 0;

    private void Mark(int slot) => _used[slot >> 6] |= 1UL << slot;

    // The first used slot at or after `from`, or −1.
    private int NextUsed(int from)
    {
        int word = from >> 6;
        if (word >= _used.Length)
        {
            return -1;
        }

        ulong bits = _used[word] & (ulong.MaxValue << from);
        while (bits == 0)
        {
            if (++word == _used.Length)
            {
                return -1;
            }

            bits = _used[word];
        }

        return (word << 6) + BitOperations.TrailingZeroCount(bits);
    }

    private int Home(int lo, int hi) => (int)((((uint)lo * 0x9E3779B1u) ^ ((uint)hi * 0x85EBCA6Bu)) >> 7) & _mask;

    private static (int Lo, int Hi) Ordered(int a, int b) => a < b ? (a, b) : (b, a);

    /// <summary>Receives the pairs whose touch ended.</summary>
    internal interface IEndedSink
    {
        /// <summary>One pair whose touch ended, in the order of the contact that began it.</summary>
        void Ended(int a, int b);
    }

    private struct Entry
    {
        public int Low;
        public int High;
        public bool LowFirst;
        public long LastStep;
        public double LastTime;
    }
}
