using System;
using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Motion interpolation for one cycle (the paper's pseudo-continuous detection, done properly).
/// Every body moves linearly in time from its last committed state (fish also turn; tail joints
/// keep the cycle's pose). Each candidate pair (<see cref="SweepPlanner"/>) is sampled on its own
/// clock, in ticks of 1/2,048 cycle: its step is the largest power-of-two number of ticks in which
/// the pair cannot move, relative to each other, more than its limit, so neither body can pass
/// through the other between two samples; and while its bounding circles are apart by a gap g
/// (<see cref="PairGap"/>), its next sample waits until it could have closed the gap (g / its
/// relative travel rate), so a pair that is far apart or moves slowly costs one cheap test or none.
/// Samples are taken in time order (<see cref="TickQueue"/>). At the first sample where pairs overlap, their
/// bodies go back to the last time they were apart and the time of first contact is refined by
/// bisection; there the contacts are resolved (<see cref="ContactResponse"/>), those bodies are
/// committed and only their pairs are planned again, with the new velocities: a contact costs
/// work in proportion to the bodies involved, not to the world. A body with
/// <see cref="PhysicsConstants.MaximumEventsPerBody"/> events in a cycle has its later contacts
/// resolved where they are found. Pairs changed at the very end of the cycle are settled without
/// motion.
/// </summary>
internal sealed partial class Stepper
{
    private const int Ticks = TickQueue.Ticks;

    private readonly World _world;
    private readonly SweepPlanner _planner;
    private readonly PairTable _table;
    private readonly TickQueue _queue = new();
    private readonly ContactLog _log;
    private readonly ContactResponse _response;
    private readonly Scheduler _scheduler;
    private readonly PairCollector _collector = new();
    private readonly int[] _eventsOf;
    private readonly MoverSet _involved;
    private readonly MoverSet _unsettled;
    private int[] _due = new int[256];
    private int _dueCount;
    private int[] _hitSlots = new int[64];
    private Hit[] _hitValues = new Hit[64];
    private int _hitCount;
    private readonly FoundHits _found = new();
    private int[] _pending = new int[16];
    private int _pendingCount;

    public Stepper(World world, ContactLog log, IBroadPhase? broadPhase = null)
    {
        _world = world;
        _log = log;
        _planner = new SweepPlanner(world, broadPhase ?? new UniformGrid());
        _table = new PairTable(_planner.Movers);
        _response = new ContactResponse(world);
        _scheduler = new Scheduler(this);
        _eventsOf = new int[_planner.Movers];
        _involved = new MoverSet(_planner.Movers);
        _unsettled = new MoverSet(_planner.Movers);
    }

    /// <summary>Distinct sample times (ticks) processed in the last cycle.</summary>
    public int SubSteps { get; private set; }

    /// <summary>Contact events (times of first contact) in the last cycle.</summary>
    public int Events { get; private set; }

    /// <summary>Deepest overlap of any pair (walls included) at the end of the last cycle, mm.</summary>
    public float LeftoverOverlap { get; private set; }

    /// <summary>Moves every body through one cycle, resolving contacts on the way.</summary>
    public void Run()
    {
        SubSteps = 0;
        Events = 0;
        for (int m = 0; m < _planner.Movers; m++)
        {
            Rebase(m, 0.0);
            _eventsOf[m] = 0;
        }

        _table.Clear();
        _queue.Clear();
        _unsettled.Clear();
        _scheduler.Time = 0.0;
        _scheduler.Settling = false;
        _planner.PlanAll(0.0, _scheduler);
        float deepest = 0f;
        int tick;
        while ((tick = _queue.NextTick()) >= 0)
        {
            TakeDue(tick);
            if (_dueCount == 0)
            {
                continue;
            }

            SubSteps++;
            deepest = MathF.Max(deepest, Sample(tick));
            if (_hitCount > 0)
            {
                HandleHits((double)tick / Ticks);
            }
        }

        for (int m = 0; m < _planner.Movers; m++)
        {
            MoveTo(m, 1.0);
        }

        if (_unsettled.Count > 0)
        {
            deepest = MathF.Max(deepest, SettleMovers(_unsettled));
        }

        LeftoverOverlap = deepest;
    }

    // The live entries of a tick.
    private void TakeDue(int tick)
    {
        _dueCount = 0;
        for (int node = _queue.Take(tick); node >= 0; node = _queue.Next(node))
        {
            int slot = _queue.SlotOf(node);
            if (_table.Alive[slot] && _table.Generation[slot] == _queue.GenerationOf(node))
            {
                if (_dueCount == _due.Length)
                {
                    Array.Resize(ref _due, _due.Length * 2);
                }

                _due[_dueCount++] = slot;
            }
        }
    }

    // Tests every due pair at the tick's time: a pair whose bounding circles are apart is not tested
    // exactly and waits until it could touch; apart pairs are scheduled again, overlapping ones
    // become hits. Returns the deepest overlap seen among pairs sampled at the end of the cycle.
    private float Sample(int tick)
    {
        double time = (double)tick / Ticks;
        for (int i = 0; i < _dueCount; i++)
        {
            MoveBodies(_table.Pair[_due[i]], time);
        }

        _hitCount = 0;
        float deepest = 0f;
        for (int i = 0; i < _dueCount; i++)
        {
            int slot = _due[i];
            CandidatePair pair = _table.Pair[slot];
            float gap = PairGap.LowerBound(_world, pair);
            Hit hit = gap > 0f ? default : PairDetector.Detect(_world, pair);
            if (hit.Depth > PhysicsConstants.ContactSlop)
            {
                AddHit(slot, hit);
                continue;
            }

            _table.LastFree[slot] = time;
            _table.ApartAtLastFree[slot] = true;
            if (tick < Ticks)
            {
                Schedule(slot, tick, time, gap);
            }
            else
            {
                deepest = MathF.Max(deepest, hit.Depth);
            }
        }

        return deepest;
    }

    // The next sample: one step on (the pair cannot pass through itself in a step), or later when
    // the pair is apart by a gap it cannot close before then (none when it cannot close it in the cycle).
    private void Schedule(int slot, int tick, double time, float gap)
    {
        long next = (long)tick + _table.Step[slot];
        if (gap > 0f)
        {
            float rate = _table.Rate[slot];
            double touch = rate > 0f ? time + (gap / rate) : double.PositiveInfinity;
            if (touch >= 1.0)
            {
                return;
            }

            next = Math.Max(next, (long)Math.Floor(touch * Ticks));
        }

        _queue.Push((int)Math.Min(next, Ticks), slot, _table.Generation[slot]);
    }

    private void AddHit(int slot, in Hit hit)
    {
        if (_hitCount == _hitSlots.Length)
        {
            Array.Resize(ref _hitSlots, _hitCount * 2);
            Array.Resize(ref _hitValues, _hitCount * 2);
        }

        _hitSlots[_hitCount] = slot;
        _hitValues[_hitCount++] = hit;
    }

    // The hits of one sample fall into clusters that share no body (a fish pushing a ball here, two
    // balls meeting there): each is its own event, taken in the order of its estimated time of first
    // contact, so one contact does not pull unrelated bodies back in time. A cluster whose pair was
    // planned again by an earlier one (a relaxation moved its body) is left to its new schedule.
    private void HandleHits(double found)
    {
        int count = _hitCount;
        _found.Load(_hitSlots, _hitValues, count, _table);
        for (int i = 0; i < count; i++)
        {
            _found.Estimate[i] = EstimatedContact(i, found);
        }

        _found.Cluster(_planner.FishCount);
        foreach (int cluster in _found.ClustersByTime())
        {
            _hitCount = 0;
            for (int i = 0; i < count; i++)
            {
                int slot = _found.Slot[i];
                if (_found.Label[i] == cluster && _table.Alive[slot] && _table.Generation[slot] == _found.Generation[i])
                {
                    AddHit(slot, _found.Value[i]);
                }
            }

            if (_hitCount > 0)
            {
                HandleEvent(found);
            }
        }
    }

    // False-position estimate of a hit's time of first contact (its last free time when unknown).
    private double EstimatedContact(int i, double found)
    {
        int slot = _found.Slot[i];
        float closing = PairMotion.ClosingRate(_world, _table.Pair[slot], _found.Value[i]);
        double guess = closing > 0f ? found - (_found.Value[i].Depth / closing) : _table.LastFree[slot];
        return Math.Clamp(guess, _table.LastFree[slot], found);
    }

    // The hits' bodies go back to the last time all were apart, the time of first contact is
    // refined, the contacts are resolved there, and those bodies are committed and planned again.
    private void HandleEvent(double found)
    {
        _involved.Clear();
        double lo = found;
        bool refine = true;
        float deepest = 0f;
        for (int i = 0; i < _hitCount; i++)
        {
            int slot = _hitSlots[i];
            lo = Math.Min(lo, _table.LastFree[slot]);
            deepest = MathF.Max(deepest, _hitValues[i].Depth);
            MarkInvolved(_table.Pair[slot]);
        }

        // Each hit sampled apart was apart at its last sample; all were apart at lo if they share it.
        bool apartAtLo = true;
        for (int i = 0; i < _hitCount; i++)
        {
            apartAtLo &= _table.LastFree[_hitSlots[i]] == lo && _table.ApartAtLastFree[_hitSlots[i]];
        }

        foreach (int m in _involved.Items)
        {
            apartAtLo &= BaseTime(m) <= lo;
            lo = Math.Max(lo, BaseTime(m));
            refine &= _eventsOf[m] < PhysicsConstants.MaximumEventsPerBody;
        }

        // An overlap no deeper than the time-of-impact tolerance is already at the contact.
        refine &= deepest > PhysicsConstants.TimeOfImpactTolerance;
        double contact = refine && lo < found ? FirstContact(lo, found, apartAtLo) : found;
        MoveInvolved(contact);
        ResolveHits(contact);
        Events++;
        foreach (int m in _involved.Items)
        {
            _eventsOf[m]++;
        }

        Relax(contact);
    }

    // Commits the involved bodies at the contact time and plans their pairs again. A correction can
    // push a body into a third one (a ball squeezed between two fish): pairs that overlap right
    // away are resolved at once, their bodies planned again, a few passes over (position
    // relaxation); what is left is sampled as usual.
    private void Relax(double contact)
    {
        for (int pass = 0; ; pass++)
        {
            foreach (int m in _involved.Items)
            {
                Rebase(m, contact);
                _table.RemoveAllOf(m);
            }

            _pendingCount = 0;
            _scheduler.Time = contact;
            _scheduler.Settling = pass < PhysicsConstants.RelaxationPasses;
            _planner.PlanFor(_involved.Items, _involved.Marks, contact, _scheduler);
            _scheduler.Settling = false;
            if (_pendingCount == 0)
            {
                return;
            }

            _involved.Clear();
            for (int i = 0; i < _pendingCount; i++)
            {
                MarkInvolved(_table.Pair[_pending[i]]);
            }

            for (int i = 0; i < _pendingCount; i++)
            {
                CandidatePair pair = _table.Pair[_pending[i]];
                Hit hit = PairDetector.Detect(_world, pair);
                if (hit.Depth > PhysicsConstants.ContactSlop)
                {
                    ContactKind kind = _response.Apply(pair, hit);
                    _log.Add(new ContactRecord(pair, hit.PartA, hit.PartB, hit.Mtv, hit.Normal, hit.Point, contact), kind);
                }
            }
        }
    }

    private void AddPending(int slot)
    {
        if (_pendingCount == _pending.Length)
        {
            Array.Resize(ref _pending, _pendingCount * 2);
        }

        _pending[_pendingCount++] = slot;
    }

    private void ResolveHits(double time)
    {
        for (int i = 0; i < _hitCount; i++)
        {
            CandidatePair pair = _table.Pair[_hitSlots[i]];
            Hit hit = PairDetector.Detect(_world, pair);
            if (hit.Depth > PhysicsConstants.ContactSlop)
            {
                ContactKind kind = _response.Apply(pair, hit);
                _log.Add(new ContactRecord(pair, hit.PartA, hit.PartB, hit.Mtv, hit.Normal, hit.Point, time), kind);
            }
        }
    }

    // Stores a planned pair and schedules its first sample after the plan time; a pair planned at
    // the very end of the cycle cannot be sampled any more: its movers are settled instead.
    // Stores a planned pair and schedules its first sample after the plan time. While settling
    // (after a contact) a pair whose bounds overlap is tested at once, and one that overlaps is
    // handed back as pending. A pair planned at the very end of the cycle cannot be sampled any
    // more: unless it is known to be apart, its movers are settled at the end.
    private sealed class Scheduler(Stepper owner) : IPairSink
    {
        public double Time;

        public bool Settling;

        public void Add(in CandidatePair pair, int moverA, int moverB, float rate)
        {
            var table = owner._table;
            int slot = table.Add(pair, moverA, moverB, rate);
            table.Step[slot] = StepTicks(pair.Limit, rate);
            table.LastFree[slot] = Time;

            // The partner may sit at another time of the cycle: both bodies are placed at the plan time.
            owner.MoveBodies(pair, Time);
            float gap = PairGap.LowerBound(owner._world, pair);
            bool apart = gap > 0f;
            if (!apart && Settling)
            {
                if (PairDetector.Detect(owner._world, pair).Depth > PhysicsConstants.ContactSlop)
                {
                    owner.AddPending(slot);
                    return;
                }

                apart = true;
            }

            table.ApartAtLastFree[slot] = apart;
            if (Time < 1.0)
            {
                owner.Schedule(slot, (int)Math.Floor(Time * Ticks), Time, gap);
            }
            else if (!apart)
            {
                owner._unsettled.Add(moverA);
                if (moverB >= 0)
                {
                    owner._unsettled.Add(moverB);
                }
            }
        }

        // Largest power of two (in ticks) during which the pair moves at most its limit.
        private static int StepTicks(float limit, float rate)
        {
            if (!(rate > 0f) || float.IsPositiveInfinity(limit))
            {
                return Ticks;
            }

            double ticks = limit / (double)rate * Ticks;
            if (ticks >= Ticks)
            {
                return Ticks;
            }

            return ticks < 2.0 ? 1 : 1 << (int)Math.Floor(Math.Log2(ticks));
        }
    }
}
