using System.Collections.Generic;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The stage that turns a sample's hits into contact events: the hits in clusters that share no
/// moving body, each event's bodies taken back to its time of first contact
/// (<see cref="FirstContactSearch"/>), the handler's response, then relaxation: the bodies the
/// response changed are committed at the contact time and planned again; pairs that overlap right
/// away (a ball squeezed between two fish) are responded to at once, a few passes over, before the
/// rest is sampled as usual. The stage owns the clusters, the event's hits and bodies, the pairs
/// pending a response and the count of events; the sample's hits it reads from the event loop's
/// sampler and leaves there.
/// </summary>
internal sealed class ContactEvents
{
    private readonly MotionWorld _world;
    private readonly PairSchedule _schedule;
    private readonly PairTable _table;
    private readonly PairSampler _sampler;
    private readonly Settling _settling;
    private readonly ContactCache _contacts;
    private readonly List<Body> _bodies;
    private readonly FirstContactSearch _search;
    private readonly Replanner _replanner;
    private readonly HitClusters _clusters = new();
    private readonly EventHits _hits = new();
    private BodySet _involved = new(0);
    private BodySet _dirty = new(0);
    private HeldContacts? _held;
    private int[] _pending = new int[16];
    private int _pendingCount;

    // A pair answered within this many of its sampling intervals is pressing.
    private const double PressingWindow = 2.0;

    /// <summary>Creates the stage over the world, its pair schedule, its settling stage (where the bodies an event touched are settled) and its contacts that persist (which pairs are pressing).</summary>
    public ContactEvents(MotionWorld world, PairSchedule schedule, Settling settling, ContactCache contacts, List<Body> bodies)
    {
        _contacts = contacts;
        _world = world;
        _schedule = schedule;
        _table = schedule.Table;
        _sampler = schedule.Sampler;
        _settling = settling;
        _bodies = bodies;
        _search = new FirstContactSearch(schedule, bodies, _hits);
        _replanner = new Replanner(this);
    }

    /// <summary>The stage that holds touching pairs (set once by the world): a re-planned pair it holds is not scheduled on its own clock.</summary>
    public HeldContacts Held
    {
        set => _held = value;
    }

    /// <summary>Contact events of the current or last step.</summary>
    public int Count { get; private set; }

    /// <summary>Pressing events (answered where found) of the current or last step.</summary>
    public int PressingCount { get; private set; }

    /// <summary>Sizes the storage for a world of <paramref name="movers"/> movers.</summary>
    public void Load(int movers)
    {
        _pending = new int[(2 * movers) + 16];
        _clusters.Reserve((2 * movers) + 64, movers);
        _hits.Reserve((2 * movers) + 64);
        _involved = new BodySet(movers);
        _dirty = new BodySet(movers);
    }

    /// <summary>Starts a step: no events yet.</summary>
    public void BeginStep()
    {
        Count = 0;
        PressingCount = 0;
        _replanner.Settling = false;
    }

    /// <summary>
    /// The hits of one sample (the event loop's sampler's) fall into clusters that share no moving
    /// body (a fish pushing a ball here, two balls meeting there): each is its own event, taken in
    /// the order of its estimated time of first contact, so one contact does not pull unrelated
    /// bodies back in time. A hit whose pair was planned again by an earlier event is left to its
    /// new schedule.
    /// </summary>
    public void HandleHits(double found)
    {
        if (_sampler.HitCount == 0)
        {
            return;
        }

        int count = _sampler.HitCount;
        _clusters.Load(_sampler.HitSlots, _sampler.HitValues, count, _table);
        for (int i = 0; i < count; i++)
        {
            _clusters.Estimate[i] = _search.Estimate(_clusters.Slot[i], _clusters.Value[i], found);
        }

        _clusters.Cluster();
        foreach (int cluster in _clusters.ClustersByTime())
        {
            _hits.Clear();
            for (int i = _clusters.FirstOf(cluster); i >= 0; i = _clusters.NextOf(i))
            {
                int slot = _clusters.Slot[i];
                if (_table.IsCurrent(slot, _clusters.Generation[i]))
                {
                    _hits.Add(slot, _clusters.Value[i]);
                }
            }

            if (_hits.Count > 0)
            {
                HandleEvent(found);
            }
        }
    }

    /// <summary>
    /// The held pairs found overlapping at a sub-step's end, answered together as one pressing
    /// event there: no search for a time of first contact (the bodies touch already), each pair
    /// answered in the order given, then relaxation and one re-plan of all their bodies. A held
    /// answer is expected every sub-step and up to a sub-step deep: it counts for no body's events,
    /// and the corrections of its relaxation (bodies pushed into others by it) count for no body's
    /// wedging (the end of the step still rejects a move left overlapping).
    /// </summary>
    public void HandleHeld(double time, ReadOnlySpan<int> slots, ReadOnlySpan<Hit> hits)
    {
        _hits.Clear();
        _hits.Reserve(slots.Length);
        _involved.Clear();
        for (int i = 0; i < slots.Length; i++)
        {
            _hits.Add(slots[i], hits[i]);
            _involved.AddPair(_table.Pair(slots[i]));
        }

        PressingCount++;
        Answer(time, pressing: true, held: true);
    }

    // One event: its bodies go back to the last time all its pairs were apart, the time of first
    // contact is found, the handler responds there, and the bodies are committed and planned again.
    private void HandleEvent(double found)
    {
        _involved.Clear();
        double lo = found;
        float deepest = 0f;
        for (int i = 0; i < _hits.Count; i++)
        {
            int slot = _hits.Slot[i];
            lo = Math.Min(lo, _table.LastFree(slot));
            deepest = MathF.Max(deepest, _hits.Value[i].Depth);
            _involved.AddPair(_table.Pair(slot));
        }

        // Each hit sampled apart was apart at its last sample; all were apart at lo if they share it.
        bool apartAtLo = true;
        foreach (int slot in _hits.Slot)
        {
            apartAtLo &= _table.LastFree(slot) == lo && _table.ApartAtLastFree(slot);
        }

        bool refine = deepest > MotionTolerances.TimeOfImpactTolerance;
        bool pressing = false;
        ReadOnlySpan<Body> movers = _schedule.Planner.MoverBodies;
        foreach (int m in _involved.Items)
        {
            Body body = movers[m];
            apartAtLo &= body.BaseTime <= lo;
            lo = Math.Max(lo, body.BaseTime);
            refine &= body.Events < MotionTolerances.MaximumEventsPerBody;
        }

        if (refine && _world.PressingContacts && AllPressing(found))
        {
            refine = false;
            pressing = true;
            PressingCount++;
        }

        double contact = refine && lo < found ? _search.Search(lo, found, apartAtLo, _involved) : found;
        Answer(contact, pressing, held: false);
    }

    // The event's bodies placed at the contact time, the handler's response to each of its pairs
    // there, then relaxation. A held answer counts for no body's events, nor do the corrections of
    // its relaxation for wedging.
    private void Answer(double contact, bool pressing, bool held)
    {
        ReadOnlySpan<Body> movers = _schedule.Planner.MoverBodies;
        MoveInvolved(contact);
        _world.Time = contact;
        Count++;
        foreach (int m in _involved.Items)
        {
            Body body = movers[m];
            if (!held)
            {
                body.Events++;
                body.EventsInPlace = body.LastEventTime == contact ? body.EventsInPlace + 1 : 0;
                body.LastEventTime = contact;
            }

            _settling.MarkTouched(m);
        }

        _world.ClearChanged();
        foreach (int slot in _hits.Slot)
        {
            Respond(_table.Pair(slot), pressing, held);
        }

        Relax(held);
    }

    // Every hit of the event is a pair answered at one of its last two samples: the bodies are in
    // contact already, and the event is answered where it was found.
    private bool AllPressing(double found)
    {
        foreach (int slot in _hits.Slot)
        {
            if (!IsPressing(slot, found))
            {
                return false;
            }
        }

        return true;
    }

    // Whether a pair was answered within its last PressingWindow sampling intervals before the time.
    private bool IsPressing(int slot, double time)
    {
        ref readonly PlannedPair pair = ref _table.Pair(slot);
        return _contacts.IsPressing(pair.A, pair.B, time, PressingWindow * _table.Interval(slot));
    }

    // The handler's response to one pair, if it still overlaps (its correction counts for wedging unless the answer is held).
    private void Respond(in PlannedPair pair, bool pressing, bool held)
    {
        Body a = _bodies[pair.A], b = _bodies[pair.B];
        Hit hit = _sampler.Memo.Detect(a, b);
        if (hit.Depth > MotionTolerances.ContactSlop)
        {
            _world.Report(new Contact(a, b, hit, _world.Time, pressing), countsForWedging: !held);
        }
    }

    private void MoveInvolved(double time)
    {
        float seconds = _schedule.Seconds;
        ReadOnlySpan<Body> movers = _schedule.Planner.MoverBodies;
        foreach (int m in _involved.Items)
        {
            movers[m].MoveTo(time, seconds);
        }
    }

    // Commits the event's bodies (and any the handler changed) at the contact time and plans their
    // pairs again. A response can push a body into a third one (a ball squeezed between two fish):
    // pairs that overlap right away are responded to at once, a few passes over; while such a
    // cascade lasts, the bodies it moves are checked against the pairs already planned for them
    // (no broad phase), and once it is quiet they are planned again, once. What is left is sampled
    // as usual.
    private void Relax(bool held)
    {
        int pass = 0;
        CommitChanged(_involved);
        Replan(pass++);
        while (_pendingCount > 0)
        {
            _involved.Clear();
            RespondPending(held);
            while (true)
            {
                _dirty.Clear();
                CommitChanged(_dirty);
                if (pass >= MotionTolerances.RelaxationPasses)
                {
                    break;
                }

                pass++;
                ScanPlanned(_dirty);
                if (_pendingCount == 0)
                {
                    break;
                }

                RespondPending(held);
            }

            Replan(pass);
        }
    }

    // The bodies the handler changed join the event (and the step's touched bodies), committed at the contact time.
    private void CommitChanged(BodySet into)
    {
        foreach (int m in _world.ChangedBodies)
        {
            into.Add(m);
            _involved.Add(m);
            _settling.MarkTouched(m);
        }

        _world.ClearChanged();
        double time = _world.Time;
        ReadOnlySpan<Body> movers = _schedule.Planner.MoverBodies;
        foreach (int m in into.Items)
        {
            movers[m].Rebase(time);
        }
    }

    // Plans every pair of the involved bodies again; while passes are left, pairs that overlap now are pending.
    private void Replan(int pass)
    {
        double time = _world.Time;
        ReadOnlySpan<Body> movers = _schedule.Planner.MoverBodies;
        foreach (int m in _involved.Items)
        {
            movers[m].Rebase(time);
            _table.RemoveAllOf(m);
        }

        _pendingCount = 0;
        _replanner.Settling = pass < MotionTolerances.RelaxationPasses;
        _schedule.Planner.PlanFor(_involved.Items, _involved.Marks, time, _replanner);
        _replanner.Settling = false;
    }

    // The pairs already planned for the given bodies that overlap now become pending (each pair once).
    private void ScanPlanned(BodySet bodies)
    {
        _pendingCount = 0;
        int stamp = _table.NextStamp();
        double time = _world.Time;
        foreach (int m in bodies.Items)
        {
            for (int edge = _table.FirstEdge(m); edge >= 0; edge = _table.NextEdge(edge))
            {
                int slot = edge >> 1;
                if (!_table.Visit(slot, stamp))
                {
                    continue;
                }

                PlannedPair pair = _table.Pair(slot);
                _schedule.MovePair(pair, time);
                Body a = _bodies[pair.A], b = _bodies[pair.B];
                if (_sampler.Memo.DetectIfNear(a, b).Depth > MotionTolerances.ContactSlop)
                {
                    AddPending(slot);
                }
            }
        }
    }

    // The handler's response to each pending pair; their bodies join the event.
    private void RespondPending(bool held)
    {
        for (int i = 0; i < _pendingCount; i++)
        {
            _involved.AddPair(_table.Pair(_pending[i]));
        }

        // A pair that overlaps right away is pressing when it was touching already.
        double time = _world.Time;
        bool pressingContacts = _world.PressingContacts;
        for (int i = 0; i < _pendingCount; i++)
        {
            int slot = _pending[i];
            Respond(_table.Pair(slot), pressingContacts && IsPressing(slot, time), held);
        }

        _pendingCount = 0;
    }

    private void AddPending(int slot)
    {
        if (_pendingCount == _pending.Length)
        {
            Array.Resize(ref _pending, _pendingCount * 2);
        }

        _pending[_pendingCount++] = slot;
    }

    // Stores a re-planned pair and schedules its first sample after the plan time. While relaxing
    // (after a contact) a pair whose bounds overlap is tested at once, and one that overlaps is
    // handed back as pending. A pair planned at the very end of the step cannot be sampled any
    // more: unless it is known to be apart, its movers are settled at the end.
    private sealed class Replanner(ContactEvents owner) : IPairSink
    {
        public bool Settling;

        public void Add(in PlannedPair pair, float rate)
        {
            PairTable table = owner._table;
            double time = owner._world.Time;
            int slot = table.Add(pair, rate, PairSchedule.Interval(pair.Limit, rate), time);

            // The partner may sit at another time of the step: both bodies are placed at the plan time.
            owner._schedule.MovePair(pair, time);
            Body a = owner._bodies[pair.A], b = owner._bodies[pair.B];
            float gap = PairTest.Gap(a, b);
            bool apart = gap > 0f;
            if (!apart && Settling)
            {
                if (owner._sampler.Memo.Detect(a, b).Depth > MotionTolerances.ContactSlop)
                {
                    owner.AddPending(slot);
                    return;
                }

                apart = true;
            }

            table.SetApartAtLastFree(slot, apart);
            if (owner._held is { } held && held.TryHold(slot, time, gap))
            {
                return;
            }

            if (time < 1.0)
            {
                owner._sampler.Schedule(table, slot, time, gap);
            }
            else if (!apart)
            {
                owner._settling.MarkTouched(pair.MoverA);
                if (pair.MoverB >= 0)
                {
                    owner._settling.MarkTouched(pair.MoverB);
                }
            }
        }
    }
}
