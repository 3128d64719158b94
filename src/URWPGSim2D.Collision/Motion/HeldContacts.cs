using System.Collections.Generic;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The stage that answers pressing pairs together on a shared clock instead of one event each.
/// The step is cut into <see cref="SubSteps"/> equal sub-steps; a pair planned while its bodies
/// touch (<see cref="ContactCache.IsTouching"/>) and their bounds could meet within a sub-step,
/// whose sampling interval is no shorter than a sub-step, is held here instead of being sampled on
/// its own clock. At each sub-step's end,
/// once the event loop has taken every sample up to it (so no body was committed later), every
/// held pair is tested there, and those that overlap are answered together as one pressing event
/// (<see cref="ContactEvents.HandleHeld"/>: no search for a time of first contact, the bodies
/// re-planned once, as a union). A held pair moves at most its limit in a sub-step (its interval
/// is at least one), so nothing passes through another between two tests. A pair whose bounds are
/// farther apart than it can close in a sub-step is not held when planned, so a contact made again
/// after parting (and the response that turned it round, which plans the pair again) is a first
/// contact, found at its time of first contact. The stage owns the held pairs and the clock.
/// </summary>
internal sealed class HeldContacts
{
    private readonly PairSchedule _schedule;
    private readonly PairTable _table;
    private readonly PairSampler _sampler;
    private readonly ContactCache _contacts;
    private readonly Settling _settling;
    private readonly List<Body> _bodies;
    private int[] _slot = [];
    private int[] _generation = [];
    private int _count;
    private bool[] _heldAtStart = [];
    private int _startSlots;
    private int[] _hitSlots = [];
    private Hit[] _hitValues = [];
    private int _hitCount;
    private int _tick;
    private int _subSteps;
    private int _room;

    /// <summary>Creates the stage over the pair schedule, the contacts that persist, the settling stage (wedged bodies' contacts) and the world's bodies (by id).</summary>
    public HeldContacts(PairSchedule schedule, ContactCache contacts, Settling settling, List<Body> bodies)
    {
        _schedule = schedule;
        _table = schedule.Table;
        _sampler = schedule.Sampler;
        _contacts = contacts;
        _settling = settling;
        _bodies = bodies;
    }

    /// <summary>Sub-steps of a step (a power of two, 1 to <see cref="TickQueue.Ticks"/>, checked by the world), or 0: no pair is held, every pair is sampled on its own clock.</summary>
    public int SubSteps
    {
        get => _subSteps;
        set
        {
            _subSteps = value;
            Size();
        }
    }

    /// <summary>Whether pairs are held.</summary>
    public bool Active => SubSteps > 0;

    /// <summary>Held pairs answered in the last step (each answer of a pair counts).</summary>
    public int Answers { get; private set; }

    /// <summary>Makes room for <paramref name="pairs"/> held pairs, the pair slots the world keeps (<see cref="PairSchedule.Room"/>; only while the stage is on: a world that holds nothing keeps no room for it).</summary>
    public void Reserve(int pairs)
    {
        _room = pairs;
        Size();
    }

    // Room for as many held pairs as the pair table reserves, or as the world can have (a small
    // world: a match of 3 movers has at most a dozen pairs), once the stage is on.
    private void Size()
    {
        int pairs = _room;
        if (_subSteps == 0 || _slot.Length >= pairs)
        {
            return;
        }

        _slot = new int[pairs];
        _generation = new int[pairs];
        _hitSlots = new int[pairs];
        _hitValues = new Hit[pairs];
        _heldAtStart = new bool[pairs];
        _count = 0;
        _hitCount = 0;
        _startSlots = 0;
    }

    /// <summary>Starts a step: nothing held, the clock at its first sub-step.</summary>
    public void BeginStep()
    {
        _count = 0;
        _tick = 0;
        Answers = 0;
        Array.Clear(_heldAtStart, 0, _startSlots);
        _startSlots = 0;
    }

    /// <summary>
    /// After the step's first plan, before any pair is sampled: the pairs planned at time 0 that
    /// the stage holds, in slot order (on the event loop's thread, so that the islands, sampled on
    /// several threads, only read which ones are held).
    /// </summary>
    public void HoldAtStart()
    {
        if (SubSteps == 0)
        {
            return;
        }

        int used = _table.Used;
        if (_heldAtStart.Length < used)
        {
            _heldAtStart = new bool[Math.Max(used, 2 * _heldAtStart.Length)];
        }

        _startSlots = used;
        for (int slot = 0; slot < used; slot++)
        {
            if (!_table.IsAlive(slot) || !CanHold(slot, 0.0))
            {
                continue;
            }

            ref readonly PlannedPair pair = ref _table.Pair(slot);
            _schedule.MovePair(pair, 0.0);
            if (TryHold(slot, 0.0, PairTest.Gap(_bodies[pair.A], _bodies[pair.B])))
            {
                _heldAtStart[slot] = true;
            }
        }
    }

    /// <summary>Whether the pair in a slot was held when the step began (its first sample is not scheduled).</summary>
    public bool IsHeldAtStart(int slot) => slot < _startSlots && _heldAtStart[slot];

    /// <summary>
    /// Holds a pair just planned at step time <paramref name="time"/> with its bounds
    /// <paramref name="gap"/> apart when the stage is active, its bodies touch
    /// (<see cref="ContactCache.IsTouching"/>) and their bounds are near enough to meet within a
    /// sub-step (a pair that parted farther is not held, so that it meets again at its time of first
    /// contact), its interval is at least a sub-step, and no sub-step's end it would have to be
    /// tested at has passed (an event found by a later sample can take its bodies back before a
    /// sub-step's end already answered: such a pair keeps its own clock until it is next planned);
    /// returns whether it did (otherwise the caller schedules it on its own clock).
    /// </summary>
    public bool TryHold(int slot, double time, float gap)
    {
        if (!CanHold(slot, time) || gap > Reach(slot))
        {
            return false;
        }

        if (_count == _slot.Length)
        {
            // Full of pairs planned again since they were held (a busy relaxation): drop those first.
            Compact();
            if (_count == _slot.Length)
            {
                Array.Resize(ref _slot, Math.Max(64, _count * 2));
                Array.Resize(ref _generation, Math.Max(64, _count * 2));
            }
        }

        _slot[_count] = slot;
        _generation[_count++] = _table.Generation(slot);
        return true;
    }

    // How far the pair's bodies can close in a sub-step, mm.
    private float Reach(int slot) => _table.Rate(slot) / SubSteps;

    // Every condition but the gap: on, a time that no passed sub-step's end is after, a long enough interval, the bodies touching.
    private bool CanHold(int slot, double time)
    {
        if (SubSteps == 0 || time >= 1.0 || time * SubSteps < _tick || _table.Interval(slot) * SubSteps < 1.0)
        {
            return false;
        }

        ref readonly PlannedPair pair = ref _table.Pair(slot);
        return _contacts.IsTouching(pair.A, pair.B);
    }

    /// <summary>The end of the current sub-step, or −1 when the step's last one was answered (or the stage is off).</summary>
    public double NextTime => SubSteps == 0 || _tick >= SubSteps ? -1.0 : (double)(_tick + 1) / SubSteps;

    /// <summary>
    /// Whether the held pairs are due: the event loop's next sample comes after the current
    /// sub-step's end (<paramref name="nextSample"/>, −1 when none is left).
    /// </summary>
    public bool DueBefore(double nextSample)
    {
        double end = NextTime;
        return end >= 0.0 && (nextSample < 0.0 || nextSample > end);
    }

    /// <summary>
    /// The current sub-step's end: every held pair still planned is tested there (its bodies moved
    /// there), the overlapping ones answered together by <paramref name="events"/>; the clock moves
    /// to the next sub-step.
    /// </summary>
    public void Run(ContactEvents events)
    {
        double time = NextTime;
        _tick++;
        Compact();
        _hitCount = 0;
        for (int i = 0; i < _count; i++)
        {
            int slot = _slot[i];
            ref readonly PlannedPair pair = ref _table.Pair(slot);
            _schedule.MovePair(pair, time);
            Body a = _bodies[pair.A], b = _bodies[pair.B];
            Hit hit = PairTest.Gap(a, b) > 0f ? default : _sampler.Memo.Detect(a, b);
            if (hit.Depth > MotionTolerances.ContactSlop)
            {
                if (!_settling.Deferred(pair, slot, time))
                {
                    AddHit(slot, hit);
                }

                continue;
            }

            _table.MarkFree(slot, time);
            if (time >= 1.0)
            {
                _sampler.NoteEndDepth(hit.Depth);
            }
        }

        if (_hitCount > 0)
        {
            _sampler.MarkSampled(time);
            Answers += _hitCount;
            events.HandleHeld(time, _hitSlots.AsSpan(0, _hitCount), _hitValues.AsSpan(0, _hitCount));
        }
    }

    // The held pairs planned again since they were held are dropped (each re-plan holds its pair again, under a new slot or generation).
    private void Compact()
    {
        int kept = 0;
        for (int i = 0; i < _count; i++)
        {
            if (_table.IsCurrent(_slot[i], _generation[i]))
            {
                _slot[kept] = _slot[i];
                _generation[kept++] = _generation[i];
            }
        }

        _count = kept;
    }

    private void AddHit(int slot, in Hit hit)
    {
        if (_hitCount == _hitSlots.Length)
        {
            Array.Resize(ref _hitSlots, Math.Max(64, _hitCount * 2));
            Array.Resize(ref _hitValues, Math.Max(64, _hitCount * 2));
        }

        _hitSlots[_hitCount] = slot;
        _hitValues[_hitCount++] = hit;
    }
}
