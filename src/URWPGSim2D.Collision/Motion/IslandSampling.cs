using System.Collections.Generic;
using System.Threading;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The stage that samples a step's first contacts island by island. The movers fall into islands
/// that cannot meet within the step as planned (see <see cref="IslandSet"/>). Each island is
/// sampled on its own, on one of <see cref="Threads"/> threads, up to its first hit: until a
/// contact response changes a motion nothing one island does concerns another. Its remaining
/// queue entries and that first sample's hits are then handed to the event loop, which carries on
/// over the whole world (a response may send a body anywhere). Islands are merged in island order,
/// so the contacts do not depend on the number of threads. On one thread every island is sampled
/// at once in the event loop's own queue (left empty by that pass), with the same result (see
/// <c>SampleIslandsTogether</c>): nothing is grouped, copied back or, until a hit needs them, built,
/// and no worker is made. The stage owns the islands, the workers
/// and the hits held for the event loop.
/// </summary>
internal sealed class IslandSampling
{
    private const int Ticks = TickQueue.Ticks;

    private readonly PairSchedule _schedule;
    private readonly PairTable _table;
    private readonly PairSampler _sampler;
    private readonly List<Body> _bodies;
    private readonly IslandSet _islands = new();
    private readonly HeldHits _heldByIsland = new();
    private readonly HeldHits _held = new();
    private readonly QueueEntries _parked = new();
    private bool[] _stopped = [];
    private int[] _perIsland = [];
    private int[] _order = [];
    private IslandWorker[] _workers = [];
    private int[] _chunkStart = new int[2];
    private IslandRunner? _runner;
    private HeldContacts? _heldContacts;
    private int _nextHeld;
    private bool _islandsBuilt;

    /// <summary>Creates the stage over the pair schedule and the world's bodies (by id).</summary>
    public IslandSampling(PairSchedule schedule, List<Body> bodies)
    {
        _schedule = schedule;
        _table = schedule.Table;
        _sampler = schedule.Sampler;
        _bodies = bodies;
    }

    /// <summary>The stage that holds touching pairs (set once by the world): a pair it held at the step's start gets no first sample.</summary>
    public HeldContacts HeldContacts
    {
        set => _heldContacts = value;
    }

    /// <summary>Threads a step may use (checked by the world).</summary>
    public int Threads { get; set; } = 1;

    /// <summary>Fewest moving bodies for which the islands are spread over <see cref="Threads"/> (checked by the world).</summary>
    public int MinimumMoversForThreads { get; set; } = 2048;

    /// <summary>Chunks of islands the last step ran at once (1: the calling thread alone).</summary>
    public int Chunks { get; private set; }

    /// <summary>Bytes the island workers' threads allocated while they ran this stage's chunks (tests).</summary>
    public long WorkerAllocatedBytes => _runner?.Allocated ?? 0L;

    /// <summary>Number of islands of the last step, or −1 when it did not need them (one thread and no hit before the event loop; tests).</summary>
    public int IslandCount => _islandsBuilt ? _islands.Count : -1;

    /// <summary>The island of a mover in the last step, or −1 when it did not need them (tests).</summary>
    public int IslandOfMover(int slot) => _islandsBuilt ? _islands.IslandOf[slot] : -1;

    /// <summary>Sizes the storage for a world of <paramref name="movers"/> movers and up to <paramref name="pairs"/> planned pairs.</summary>
    public void Load(int movers, int pairs)
    {
        _islands.Load(movers, pairs);
        _heldByIsland.Reserve((2 * movers) + 64);
        _held.Reserve((2 * movers) + 64);
        _parked.Reserve((8 * movers) + 256);
        _stopped = new bool[movers];
        _perIsland = new int[movers + 1];
        _order = new int[(8 * movers) + 256];
        foreach (IslandWorker worker in _workers)
        {
            worker.Reserve(movers);
        }
    }

    /// <summary>After the first plan (pairs recorded, not yet sampled): islands found, each sampled up to its first hit, the results handed to the event loop.</summary>
    public void SampleFirst()
    {
        _islandsBuilt = false;
        int wanted = 1;
        if (Threads > 1 && _schedule.Planner.Movers >= MinimumMoversForThreads)
        {
            BuildIslands();
            wanted = Math.Min(Threads, Math.Max(1, _islands.Count));
        }

        if (wanted == 1)
        {
            Chunks = 1;
            SampleIslandsTogether();
            return;
        }

        EnsureWorkers(wanted);
        _islands.Group(_table);
        if (_chunkStart.Length < wanted + 1)
        {
            _chunkStart = new int[wanted + 1];
        }

        int chunks = _islands.Split(wanted, _chunkStart);
        Chunks = chunks;
        _runner ??= new IslandRunner(this);
        IslandPool.Run(_runner, chunks);

        // Merged in island order (chunks are contiguous ranges of islands, in order).
        _heldByIsland.Clear();
        for (int c = 0; c < chunks; c++)
        {
            IslandWorker worker = _workers[c];
            _sampler.Absorb(worker.Sampler);
            QueueEntries handoff = worker.Handoff;
            ReadOnlySpan<int> ticks = handoff.Tick, slots = handoff.Slot, generations = handoff.Generation;
            for (int i = 0; i < handoff.Count; i++)
            {
                _sampler.Queue.PushTick(ticks[i], slots[i], generations[i]);
            }

            _heldByIsland.AddAll(worker.Held);
        }

        _held.SortByTick(_heldByIsland);
        _nextHeld = 0;
    }

    // One thread: every island sampled at once in one queue, in time order, each up to its first hit
    // (then its later entries are parked). The same samples in the same order within each island as
    // when each island runs alone (islands share no mover, and a pair's clock is its own); the held
    // hits (by tick, then island) and the parked entries (by island, then tick) are handed to the
    // event loop in the order the islands one by one give. The pass runs in the event loop's sampler:
    // its queue is empty at the end, its sampled ticks and deepest end overlap are the pass's.
    private void SampleIslandsTogether()
    {
        PairSampler sampler = _sampler;
        sampler.BeginStep();
        float seconds = _schedule.Seconds;
        for (int slot = 0; slot < _table.Used; slot++)
        {
            if (_table.IsAlive(slot))
            {
                ScheduleFirst(sampler, slot, seconds);
            }
        }

        _held.Clear();
        _parked.Clear();
        _nextHeld = 0;
        bool anyStopped = false;
        ReadOnlySpan<int> islandOf = _islands.IslandOf;
        for (double time; (time = sampler.Queue.NextTime()) >= 0.0;)
        {
            int due = anyStopped
                ? sampler.TakeDueOfRunning(time, _table, islandOf, _stopped, _parked)
                : sampler.TakeDue(time, _table);
            if (due == 0)
            {
                continue;
            }

            sampler.SampleDue(time, _table, _bodies, seconds, null);
            if (sampler.HitCount > 0)
            {
                HoldByIsland(sampler, (int)(time * Ticks));
                anyStopped = true;
            }
        }

        if (anyStopped)
        {
            HandParkedToQueue();
            for (int i = 0; i < _held.Count; i++)
            {
                _stopped[IslandOfSlot(_held.Slot[i])] = false;
            }
        }
    }

    // A planned pair's first sample, scheduled from the start of the step by its gap there.
    private void ScheduleFirst(PairSampler sampler, int slot, float seconds)
    {
        if (_heldContacts is { } held && held.IsHeldAtStart(slot))
        {
            return;
        }

        ref readonly PlannedPair pair = ref _table.Pair(slot);
        PairSampler.MovePair(_bodies, pair, 0.0, seconds);
        float gap = PairTest.Gap(_bodies[pair.A], _bodies[pair.B]);
        _table.SetApartAtLastFree(slot, gap > 0f);
        sampler.Schedule(_table, slot, 0.0, gap);
    }

    // The hits of one sample, held in island order (stable: a sampled island's hits keep their order); their islands stop.
    private void HoldByIsland(PairSampler sampler, int tick)
    {
        BuildIslands();
        ReadOnlySpan<int> hitSlots = sampler.HitSlots;
        ReadOnlySpan<Hit> hitValues = sampler.HitValues;
        int count = hitSlots.Length;
        if (_order.Length < count)
        {
            _order = new int[count * 2];
        }

        for (int h = 0; h < count; h++)
        {
            int island = IslandOfSlot(hitSlots[h]);
            int at = h;
            while (at > 0 && IslandOfSlot(hitSlots[_order[at - 1]]) > island)
            {
                _order[at] = _order[at - 1];
                at--;
            }

            _order[at] = h;
        }

        for (int i = 0; i < count; i++)
        {
            int h = _order[i];
            int slot = hitSlots[h];
            _held.Add(tick, slot, _table.Generation(slot), hitValues[h]);
            _stopped[IslandOfSlot(slot)] = true;
        }
    }

    // The parked entries (by tick, queue order within one) pushed into the event loop's queue by island, then tick (a stable counting sort).
    private void HandParkedToQueue()
    {
        int n = _parked.Count, islands = _islands.Count;
        if (n == 0)
        {
            return;
        }

        if (_order.Length < n)
        {
            _order = new int[n * 2];
        }

        Span<int> start = _perIsland.AsSpan(0, islands + 1);
        start.Clear();
        ReadOnlySpan<int> ticks = _parked.Tick, slots = _parked.Slot, generations = _parked.Generation;
        for (int i = 0; i < n; i++)
        {
            start[IslandOfSlot(slots[i]) + 1]++;
        }

        for (int k = 1; k <= islands; k++)
        {
            start[k] += start[k - 1];
        }

        for (int i = 0; i < n; i++)
        {
            _order[start[IslandOfSlot(slots[i])]++] = i;
        }

        for (int k = 0; k < n; k++)
        {
            int i = _order[k];
            _sampler.Queue.PushTick(ticks[i], slots[i], generations[i]);
        }
    }

    // The islands of the pairs planned at the start of the step, found once (the pre-pass does not change the plan).
    private void BuildIslands()
    {
        if (!_islandsBuilt)
        {
            _islands.Build(_table);
            _islandsBuilt = true;
        }
    }

    private int IslandOfSlot(int slot) => _islands.IslandOf[_table.Pair(slot).MoverA];

    private void EnsureWorkers(int count)
    {
        if (_workers.Length >= count)
        {
            return;
        }

        int old = _workers.Length;
        Array.Resize(ref _workers, count);
        for (int w = old; w < count; w++)
        {
            _workers[w] = new IslandWorker();
            _workers[w].Reserve(_schedule.Planner.Movers);
        }
    }

    // One chunk of islands, each sampled alone in the worker's own queue until its first hit or the end of the step.
    private void RunChunk(int chunk)
    {
        IslandWorker worker = _workers[chunk];
        PairSampler sampler = worker.Sampler;
        sampler.BeginStep();
        worker.Handoff.Clear();
        worker.Held.Clear();
        ReadOnlySpan<int> start = _islands.PairStart, slots = _islands.PairSlot;
        float seconds = _schedule.Seconds;
        for (int island = _chunkStart[chunk]; island < _chunkStart[chunk + 1]; island++)
        {
            // The pairs' first samples, scheduled from the start of the step in slot (plan) order.
            for (int i = start[island]; i < start[island + 1]; i++)
            {
                ScheduleFirst(sampler, slots[i], seconds);
            }

            for (double time; (time = sampler.Queue.NextTime()) >= 0.0;)
            {
                if (sampler.TakeDue(time, _table) == 0)
                {
                    continue;
                }

                sampler.SampleDue(time, _table, _bodies, seconds, null);
                if (sampler.HitCount > 0)
                {
                    int tick = (int)(time * Ticks);
                    ReadOnlySpan<int> hitSlots = sampler.HitSlots;
                    ReadOnlySpan<Hit> hitValues = sampler.HitValues;
                    for (int h = 0; h < hitSlots.Length; h++)
                    {
                        int slot = hitSlots[h];
                        worker.Held.Add(tick, slot, _table.Generation(slot), hitValues[h]);
                    }

                    sampler.Queue.DrainInto(worker.Handoff);
                    break;
                }
            }
        }
    }

    /// <summary>The earliest time with queue entries (the event loop's) or held hits, or −1.</summary>
    public double NextTime()
    {
        double queued = _sampler.Queue.NextTime();
        if (_nextHeld == _held.Count)
        {
            return queued;
        }

        double held = (double)_held.Tick[_nextHeld] / Ticks;
        return queued < 0.0 ? held : Math.Min(queued, held);
    }

    /// <summary>The held hits of a time whose pairs were not planned again since, placed at the time and added to the event loop's hits; returns their number.</summary>
    public int TakeHeld(double time)
    {
        int tick = (int)(time * Ticks);
        int count = 0;
        for (; _nextHeld < _held.Count && _held.Tick[_nextHeld] == tick; _nextHeld++)
        {
            int slot = _held.Slot[_nextHeld];
            if (_table.IsCurrent(slot, _held.Generation[_nextHeld]))
            {
                _schedule.MovePair(_table.Pair(slot), time);
                _sampler.AddHit(slot, _held.Value[_nextHeld]);
                count++;
            }
        }

        return count;
    }

    private sealed class IslandRunner(IslandSampling owner) : IslandPool.IChunkWork
    {
        private long _allocated;

        public long Allocated => Interlocked.Read(ref _allocated);

        public void RunChunk(int chunk) => owner.RunChunk(chunk);

        public void CountAllocated(long bytes) => Interlocked.Add(ref _allocated, bytes);
    }
}
