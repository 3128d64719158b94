using System.Collections.Generic;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Samples candidate pairs on their own clocks: the queue of sample times, the pairs due at a
/// time, the hits a sample finds, the exact tests it remembers, and the ticks it sampled. The
/// motion world has one for its event loop, which also samples the islands on one thread; each island
/// worker of a step on several threads has its own, so that islands sampled on several threads
/// share nothing but the pair table's slots of their own pairs. Storage grows by doubling, never
/// shrinks.
/// </summary>
internal sealed class PairSampler
{
    private const int Ticks = TickQueue.Ticks;

    private ulong[] _sampled = new ulong[(Ticks + 64) / 64];
    private int[] _due = new int[256];
    private int _dueCount;
    private int[] _hitSlots = new int[64];
    private Hit[] _hitValues = new Hit[64];

    /// <summary>When each pair is next sampled.</summary>
    public TickQueue Queue { get; } = new();

    /// <summary>The last exact tests.</summary>
    public TestMemo Memo { get; } = new();

    /// <summary>Pair slot of each hit of the current sample.</summary>
    public ReadOnlySpan<int> HitSlots => _hitSlots.AsSpan(0, HitCount);

    /// <summary>The contact of each hit of the current sample.</summary>
    public ReadOnlySpan<Hit> HitValues => _hitValues.AsSpan(0, HitCount);

    /// <summary>Number of hits of the current sample (a take of due pairs starts a new sample).</summary>
    public int HitCount { get; private set; }

    /// <summary>Deepest overlap (within the contact slop) of the pairs sampled at the end of the step, mm.</summary>
    public float DeepestAtEnd { get; private set; }

    /// <summary>Distinct sample times of the last step, counted when its event loop ends (<see cref="EndStep"/>).</summary>
    public int SubSteps { get; private set; }

    /// <summary>Makes room for a busy step of a world of <paramref name="movers"/> movers.</summary>
    public void Reserve(int movers)
    {
        Queue.Reserve((32 * movers) + 1024);
        _due = new int[(8 * movers) + 256];
        _hitSlots = new int[(2 * movers) + 64];
        _hitValues = new Hit[(2 * movers) + 64];
        Memo.Reserve(movers);
    }

    /// <summary>Starts a step: no entries, no sampled ticks.</summary>
    public void BeginStep()
    {
        Queue.Clear();
        Array.Clear(_sampled);
        HitCount = 0;
        DeepestAtEnd = 0f;
        SubSteps = 0;
    }

    /// <summary>The event loop of the step is over: its distinct sample times are counted.</summary>
    public void EndStep() => SubSteps = SampledTicks();

    /// <summary>Takes the live entries of a sample time, starting a new sample (no hits yet); returns their number (the tick counts as sampled when there are any).</summary>
    public int TakeDue(double time, PairTable table)
    {
        _dueCount = 0;
        HitCount = 0;
        int first = Queue.Take(time);
        for (int node = first; node >= 0; node = Queue.Next(node))
        {
            int slot = Queue.SlotOf(node);
            if (table.IsCurrent(slot, Queue.GenerationOf(node)))
            {
                AddDue(slot);
            }
        }

        return EndTake(time, first);
    }

    /// <summary>
    /// Takes the entries of a sample time as <see cref="TakeDue"/> does, except those of pairs whose
    /// island has stopped (<paramref name="stopped"/> by island, <paramref name="islandOf"/> by mover):
    /// these are appended to <paramref name="parked"/> in queue order. Returns the number of entries
    /// due (the tick counts as sampled when there are any).
    /// </summary>
    public int TakeDueOfRunning(double time, PairTable table, ReadOnlySpan<int> islandOf, ReadOnlySpan<bool> stopped, QueueEntries parked)
    {
        _dueCount = 0;
        HitCount = 0;
        int tick = (int)(time * Ticks);
        int first = Queue.Take(time);
        for (int node = first; node >= 0; node = Queue.Next(node))
        {
            int slot = Queue.SlotOf(node);
            if (stopped[islandOf[table.Pair(slot).MoverA]])
            {
                parked.Add(tick, slot, Queue.GenerationOf(node));
            }
            else if (table.IsCurrent(slot, Queue.GenerationOf(node)))
            {
                AddDue(slot);
            }
        }

        return EndTake(time, first);
    }

    // One more pair due at the sample (the list grows only while a world's first busy steps size it).
    private void AddDue(int slot)
    {
        if (_dueCount == _due.Length)
        {
            Array.Resize(ref _due, _due.Length * 2);
        }

        _due[_dueCount++] = slot;
    }

    // The taken nodes go back to the queue's free list; the tick counts as sampled when any was due.
    private int EndTake(double time, int first)
    {
        Queue.Recycle(first);
        if (_dueCount > 0)
        {
            MarkSampled(time);
        }

        return _dueCount;
    }

    /// <summary>
    /// Tests every due pair at the time: a pair whose bounds are apart is not tested exactly and waits
    /// until it could touch; apart pairs are scheduled again, overlapping ones are added to the hits
    /// (unless <paramref name="wedging"/> leaves them to the end of the step: a wedged body's).
    /// </summary>
    public void SampleDue(double time, PairTable table, List<Body> bodies, float seconds, Settling? wedging)
    {
        for (int i = 0; i < _dueCount; i++)
        {
            MovePair(bodies, table.Pair(_due[i]), time, seconds);
        }

        for (int i = 0; i < _dueCount; i++)
        {
            int slot = _due[i];
            ref readonly PlannedPair pair = ref table.Pair(slot);
            Body a = bodies[pair.A], b = bodies[pair.B];
            float gap = PairTest.Gap(a, b);
            Hit hit = gap > 0f ? default : Memo.Detect(a, b);
            if (hit.Depth > MotionTolerances.ContactSlop)
            {
                if (wedging is null || !wedging.Deferred(pair, slot, time))
                {
                    AddHit(slot, hit);
                }

                continue;
            }

            table.MarkFree(slot, time);
            if (time < 1.0)
            {
                Schedule(table, slot, time, gap);
            }
            else
            {
                DeepestAtEnd = MathF.Max(DeepestAtEnd, hit.Depth);
            }
        }
    }

    /// <summary>
    /// The next sample: one interval on (the pair cannot pass through itself in an interval), or later
    /// when the pair is apart by a gap it cannot close before then (none when it cannot close it in the step).
    /// </summary>
    public void Schedule(PairTable table, int slot, double time, float gap)
    {
        double next = Grid(time) + table.Interval(slot);
        if (gap > 0f)
        {
            float rate = table.Rate(slot);
            double touch = rate > 0f ? time + (gap / rate) : double.PositiveInfinity;
            if (touch >= 1.0)
            {
                return;
            }

            next = Math.Max(next, Math.Floor(touch * Ticks) / Ticks);
        }

        Queue.Push(Math.Min(next, 1.0), slot, table.Generation(slot));
    }

    /// <summary>A pair tested at the end of the step outside the queue (a held pair) overlapping by <paramref name="depth"/> (within the contact slop).</summary>
    public void NoteEndDepth(float depth) => DeepestAtEnd = MathF.Max(DeepestAtEnd, depth);

    /// <summary>Adds a hit of the current sample.</summary>
    public void AddHit(int slot, in Hit hit)
    {
        if (HitCount == _hitSlots.Length)
        {
            _hitSlots = Resized(_hitSlots, HitCount * 2);
            _hitValues = Resized(_hitValues, HitCount * 2);
        }

        _hitSlots[HitCount] = slot;
        _hitValues[HitCount++] = hit;
    }

    /// <summary>Marks a grid time as sampled.</summary>
    public void MarkSampled(double time)
    {
        int tick = (int)(time * Ticks);
        _sampled[tick >> 6] |= 1UL << (tick & 63);
    }

    /// <summary>Adds another sampler's sampled ticks, deepest end overlap and exact tests to this one's.</summary>
    public void Absorb(PairSampler other)
    {
        Memo.TakeTests(other.Memo);
        for (int w = 0; w < _sampled.Length; w++)
        {
            _sampled[w] |= other._sampled[w];
        }

        DeepestAtEnd = MathF.Max(DeepestAtEnd, other.DeepestAtEnd);
    }

    // Number of distinct ticks sampled this step.
    private int SampledTicks()
    {
        int count = 0;
        foreach (ulong word in _sampled)
        {
            count += BitOperations.PopCount(word);
        }

        return count;
    }

    /// <summary>Places both bodies of a pair at a step time (a static partner stays).</summary>
    public static void MovePair(List<Body> bodies, in PlannedPair p, double time, float seconds)
    {
        bodies[p.A].MoveTo(time, seconds);
        if (p.MoverB >= 0)
        {
            bodies[p.B].MoveTo(time, seconds);
        }
    }

    // The grid time at or before a time.
    private static double Grid(double time) => Math.Floor(time * Ticks) / Ticks;

    private static T[] Resized<T>(T[] array, int size)
    {
        Array.Resize(ref array, size);
        return array;
    }
}
