using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Pseudo-continuous collision detection over a world of bodies for one step of time: every
/// moving body moves linearly from its state at the start of the step (translation and turning;
/// a fish's joints keep their angles unless set to turn over the step, <see cref="SetJointTargets"/>), and every contact is reported, in time order, at its time
/// of first contact through an <see cref="IContactHandler"/> that applies the caller's response.
/// Nothing is missed and nothing tunnels: each candidate pair (found by the broad phase, a
/// uniform grid by default) is sampled on its own clock, often enough that neither
/// body can pass through the other between two samples, and not at all while its bounding circles
/// are too far apart to meet. After the step no two bodies overlap by more than 0.5 mm: a body
/// whose response leaves it inside another one has its move rejected. The same bodies and calls
/// give the same contacts, bit for bit. After warm-up a step allocates nothing.
/// </summary>
/// <remarks>See docs/motion.md for the algorithm and a worked example.</remarks>
public sealed partial class MotionWorld
{
    // The stages of a step, each owning its data: the candidate pairs and when each is sampled,
    // the first samples island by island, contact events (time of first contact, response,
    // relaxation), and the end of the step (settling, wedged bodies, rejected moves). The world
    // itself owns the bodies and the bodies a response changed.
    private readonly PairSchedule _schedule;
    private readonly IslandSampling _islands;
    private readonly ContactEvents _events;
    private readonly Settling _settling;
    private readonly ContactCache _contacts = new();
    private readonly HeldContacts _held;
    private IContactHandler? _handler;
    private bool _pressingContacts;

    /// <summary>Creates an empty motion world.</summary>
    /// <param name="broadPhase">The broad phase over the bodies' swept boxes; every kind gives the same contacts.</param>
    /// <exception cref="ArgumentException"><paramref name="broadPhase"/> is not a defined kind.</exception>
    public MotionWorld(BroadPhaseKind broadPhase = BroadPhaseKind.UniformGrid)
        : this(BroadPhaseFactory.Create(broadPhase, nameof(broadPhase)))
    {
    }

    /// <summary>Creates an empty motion world over a given broad phase instance (tests: a grid of a chosen cell size).</summary>
    /// <param name="broadPhase">The broad phase over the bodies' swept boxes.</param>
    internal MotionWorld(IBroadPhase broadPhase)
    {
        ArgumentNullException.ThrowIfNull(broadPhase);
        _schedule = new PairSchedule(broadPhase, _bodies);
        _settling = new Settling(this, _schedule, _bodies);
        _events = new ContactEvents(this, _schedule, _settling, _contacts, _bodies);
        _islands = new IslandSampling(_schedule, _bodies);
        _held = new HeldContacts(_schedule, _contacts, _settling, _bodies);
        _events.Held = _held;
        _islands.HeldContacts = _held;
    }

    /// <summary>
    /// Sub-steps on which touching pairs are answered together (held contacts), or 0 (the default):
    /// every pair is sampled on its own clock and every contact is an event at its time of first
    /// contact. With K sub-steps the step is cut into K equal parts; a pair whose bodies touch (the
    /// handler answered it in this step or the last), whose bounds could meet within a sub-step and
    /// whose sampling interval is at least a sub-step is not sampled on its own clock: it is tested
    /// at every sub-step's end, and the pairs found overlapping there are answered together as one
    /// pressing event (<see cref="Contact.Pressing"/>; no search for a time of first contact, their
    /// bodies planned again once). A held pair moves at most its sampling limit in a sub-step, so
    /// nothing passes through another. A first contact, or a contact made again after the bodies
    /// parted farther than they can close in a sub-step, is still found at its time of first
    /// contact. A sub-step's held answers count as one event (<see cref="Events"/>,
    /// <see cref="PressingEvents"/>; <see cref="HeldAnswers"/> counts the pairs), and count for no
    /// body's events or wedging. A power of two up to 2,048; the match server plays on 2.
    /// </summary>
    /// <exception cref="ArgumentException">The value is not 0 or a power of two up to 2,048, or a step is running.</exception>
    public int HeldSubSteps
    {
        get => _held.SubSteps;
        set
        {
            if (value < 0 || value > TickQueue.Ticks || (value > 0 && !BitOperations.IsPow2(value)))
            {
                throw new ArgumentException($"held sub-steps must be 0 or a power of two up to {TickQueue.Ticks}, got {value}", nameof(value));
            }

            if (_stepping)
            {
                throw new ArgumentException("held sub-steps cannot change while a step runs", nameof(value));
            }

            _held.SubSteps = value;
        }
    }

    /// <summary>Held pairs answered in the last step: the pairs found overlapping at a sub-step's end and answered together (see <see cref="HeldSubSteps"/>).</summary>
    public int HeldAnswers => _held.Answers;

    /// <summary>The time within the current step (a fraction 0 … 1 of its duration): during a handler call, the contact's time.</summary>
    public double Time { get; internal set; }

    /// <summary>Distinct sample times of the last step.</summary>
    public int SubSteps => _schedule.Sampler.SubSteps;

    /// <summary>Contact events of the last step: those found at their time of first contact and the pressing ones (<see cref="PressingEvents"/>).</summary>
    public int Events => _events.Count;

    /// <summary>Contact events of the last step that were pressing: answered where a sample found them, without a search for the time of first contact (see <see cref="PressingContacts"/>).</summary>
    public int PressingEvents => _events.PressingCount;

    /// <summary>
    /// Exact pair tests since the last step began: the narrow-phase tests of two bodies that its
    /// samples, searches for times of first contact, responses (<see cref="Detect"/>) and settling
    /// ran, not counting a test answered from memory (the same pair with both bodies exactly where
    /// they were); a <see cref="Detect"/> or <see cref="Settle"/> between steps counts with the last
    /// step. A measure of a step's work that does not depend on the machine it runs on. The same
    /// world, steps and handler give the same count; on several <see cref="Threads"/> the count can
    /// differ from one thread's (each thread remembers its own tests), the contacts never do.
    /// </summary>
    public int ExactTests => _schedule.Sampler.Memo.Tests;

    /// <summary>Pairs of bodies touching now: answered by the handler in the current or last step (see <see cref="IContactHandler.OnTouchBegan"/>).</summary>
    public int TouchingPairs => _contacts.Count;

    /// <summary>
    /// Whether a pair that is already touching is answered where a sample finds it overlapping,
    /// without a search for its time of first contact (false by default: every contact is
    /// answered at its time of first contact). An event is pressing when every pair of it was
    /// answered at one of its last two samples (a fish pushing a ball along, a ball held against
    /// a wall): the bodies are in contact already, and the event is answered where the sample
    /// found it, as deep as the bodies moved into each other since (at most the pair's sampling
    /// limit, so nothing passes through). A first contact is always found at its time of first
    /// contact. This saves the search and the events it leads to (a 1,000-body crowd: about a
    /// third of its exact tests), but a response that splits its correction between the two
    /// bodies then pushes each back by its share of a deeper overlap than at the time of first
    /// contact: a fish pushing a ball loses ground it does not lose otherwise, which is why the
    /// match server leaves this off. <see cref="Contact.Pressing"/> marks such contacts.
    /// </summary>
    /// <exception cref="ArgumentException">A step is running.</exception>
    public bool PressingContacts
    {
        get => _pressingContacts;
        set
        {
            if (_stepping)
            {
                throw new ArgumentException("pressing contacts cannot be switched while a step runs", nameof(value));
            }

            _pressingContacts = value;
        }
    }

    /// <summary>
    /// Whether two bodies are touching now: the handler answered a contact of theirs in the current
    /// or last step. A touch begins with its first answer (<see cref="IContactHandler.OnTouchBegan"/>)
    /// and ends after a whole step without one (<see cref="IContactHandler.OnTouchEnded"/>).
    /// </summary>
    /// <param name="a">One body's id.</param>
    /// <param name="b">The other body's id.</param>
    /// <returns>True when they touch.</returns>
    /// <exception cref="ArgumentException">An id is not one of this motion world's bodies now.</exception>
    public bool IsTouching(BodyId a, BodyId b)
    {
        Body first = Existing(a, nameof(a)), second = Existing(b, nameof(b));
        return _contacts.IsTouching(first.Id, second.Id);
    }

    /// <summary>Bodies whose move was rejected in the last step (see <see cref="IContactHandler.OnMoveRejected"/>).</summary>
    public int RejectedMoves => _settling.RejectedMoves;

    /// <summary>Deepest overlap of any pair (walls included) at the end of the last step, mm.</summary>
    public float LeftoverOverlap => _settling.LeftoverOverlap;

    /// <summary>
    /// Moves every body through one step of <paramref name="seconds"/>, reporting each contact to
    /// <paramref name="handler"/> at its time of first contact, in time order.
    /// </summary>
    /// <param name="seconds">Duration of the step, s (positive and finite).</param>
    /// <param name="handler">The contact response.</param>
    /// <exception cref="ArgumentException"><paramref name="seconds"/> is not positive and finite.</exception>
    /// <exception cref="ArgumentNullException"><paramref name="handler"/> is null.</exception>
    public void Step(float seconds, IContactHandler handler)
    {
        Begin(seconds, handler);
        _islands.SampleFirst();
        PairSampler sampler = _schedule.Sampler;
        PairTable table = _schedule.Table;
        for (double time; (time = _islands.NextTime()) >= 0.0 || _held.NextTime >= 0.0;)
        {
            if (_held.DueBefore(time))
            {
                _held.Run(_events);
                continue;
            }

            int due = sampler.TakeDue(time, table);
            if (_islands.TakeHeld(time) + due > 0)
            {
                sampler.MarkSampled(time);
                sampler.SampleDue(time, table, _bodies, seconds, _settling);
                _events.HandleHits(time);
            }
        }

        sampler.EndStep();
        MoveAllTo(1.0);
        _settling.EndStep(sampler.DeepestAtEnd);
        End();
    }

    /// <summary>
    /// Resolves overlaps left by jumps between steps (bodies placed with <see cref="SetPose"/>):
    /// every pair of moving bodies that overlaps now goes to <paramref name="handler"/>, a few passes
    /// over, without motion; a body still inside another one afterwards has its move rejected.
    /// </summary>
    /// <param name="handler">The contact response.</param>
    /// <exception cref="ArgumentNullException"><paramref name="handler"/> is null.</exception>
    /// <exception cref="ArgumentException">A step is running.</exception>
    public void Settle(IContactHandler handler)
    {
        ArgumentNullException.ThrowIfNull(handler);
        if (_stepping)
        {
            throw new ArgumentException("Settle cannot be called while a step runs", nameof(handler));
        }

        EnsureLoaded();
        _handler = handler;
        _stepping = true;
        _queryMoversMoved = true;
        Time = 0.0;
        _settling.SettleAll();
        _stepping = false;
        foreach (Body body in _schedule.Planner.MoverBodies)
        {
            Remember(body);
        }

        _handler = null;
    }

    /// <summary>Deepest overlap among all pairs of bodies now (no motion), mm.</summary>
    /// <returns>The depth, 0 when nothing overlaps.</returns>
    public float MeasureOverlap()
    {
        EnsureLoaded();
        return _settling.MeasureOverlap();
    }

    /// <summary>
    /// Rejects a moving body's move in the current step, from a handler (a response that finds the
    /// body wedged): it goes back to where it began the step (its pose and joints at the end of the
    /// previous step, or where it was last placed between steps), at rest (own velocity and drift
    /// zero), and <see cref="IContactHandler.OnMoveRejected"/> is called, as for a move the motion world
    /// rejects itself. While <see cref="Settle"/> runs after a step, the move rejected is that
    /// step's. The body stays there for the rest of the step unless moved again.
    /// </summary>
    /// <param name="body">The body's id.</param>
    /// <exception cref="ArgumentException">The body does not move, or no step (or <see cref="Settle"/>) is running.</exception>
    public void RejectMove(BodyId body)
    {
        Body b = Moving(body, null, nameof(body));
        if (!_stepping)
        {
            throw new ArgumentException($"{body}: a move can be rejected only from a handler, while a step or Settle runs", nameof(body));
        }

        Touch(b);
        _settling.RejectToStepStart(b);
    }

    /// <summary>When a body counts as wedged (its contacts left to the end of the step, its move rejected if still overlapping there, or rejected at once after too many deep corrections); the defaults of <see cref="WedgePolicy"/> until set.</summary>
    /// <exception cref="ArgumentNullException">The value is null.</exception>
    /// <exception cref="ArgumentException">A step is running.</exception>
    public WedgePolicy Wedging
    {
        get => _settling.Policy;
        set
        {
            ArgumentNullException.ThrowIfNull(value);
            if (_stepping)
            {
                throw new ArgumentException("the wedge policy cannot change while a step runs", nameof(value));
            }

            _settling.Policy = value;
        }
    }

    /// <summary>
    /// Fewest moving bodies for which the islands are spread over <see cref="Threads"/> (2,048 by
    /// default): smaller worlds use the calling thread alone, with the same result (at 1,000 bodies
    /// two threads measured no faster). Lower it to spread small worlds too.
    /// </summary>
    /// <exception cref="ArgumentException">The value is less than 1.</exception>
    public int MinimumMoversForThreads
    {
        get => _islands.MinimumMoversForThreads;
        set
        {
            if (value < 1)
            {
                throw new ArgumentException($"minimumMoversForThreads must be at least 1, got {value}", nameof(value));
            }

            _islands.MinimumMoversForThreads = value;
        }
    }

    /// <summary>
    /// Threads a step may use (1 by default): the islands of bodies that cannot meet within the step
    /// are sampled on up to this many threads up to their first contact. The contacts, poses and
    /// counts are the same whatever the number; a world of fewer than 2,048 moving bodies uses the
    /// calling thread alone. Threads are created once, on first need, and shared by all motion worlds.
    /// </summary>
    /// <exception cref="ArgumentException">The value is below 1 or above 1024, or a step is running.</exception>
    public int Threads
    {
        get => _islands.Threads;
        set
        {
            if (value < 1 || value > 1024)
            {
                throw new ArgumentException($"threads must be 1 to 1024, got {value}", nameof(value));
            }

            if (_stepping)
            {
                throw new ArgumentException("threads cannot change while a step runs", nameof(value));
            }

            _islands.Threads = value;
        }
    }

    /// <summary>Chunks of islands the last step ran at once (1: the calling thread alone).</summary>
    public int Chunks => _islands.Chunks;

    /// <summary>Bytes the island workers' threads allocated while they ran this motion world's chunks (tests).</summary>
    internal long WorkerAllocatedBytes => _islands.WorkerAllocatedBytes;

    /// <summary>Number of islands of the last step, or −1 when it did not need them (one thread and no hit before the event loop; tests).</summary>
    internal int IslandCount => _islands.IslandCount;

    /// <summary>The island of a moving body in the last step, or −1 when it did not need them (tests).</summary>
    internal int IslandOf(BodyId body) => _islands.IslandOfMover(Get(body).Slot);

    /// <summary>A mover's swept circle as the last step planned it (tests).</summary>
    internal Disc SweptCircleOf(BodyId body) => _schedule.Planner.SweptCircle(Get(body).Slot);

    /// <summary>The response to one contact, from the handler, after its bodies are involved in the order the response moves them; a pressing contact's corrections, or any when <paramref name="countsForWedging"/> is false, count for no body's wedging.</summary>
    internal void Report(in Contact contact, bool countsForWedging = true)
    {
        Body a = Get(contact.BodyA), b = Get(contact.BodyB);
        InvolveInOrder(a, b);
        IContactHandler handler = _handler!;
        if (_contacts.Touch(a.Id, b.Id, Time))
        {
            handler.OnTouchBegan(this, contact.BodyA, contact.BodyB);
        }

        Vector2 positionA = a.Position, positionB = b.Position;
        float headingA = a.Heading, headingB = b.Heading;
        handler.OnSeparate(this, contact);
        bool counts = !contact.Pressing && countsForWedging;
        bool correctedA = counts && (a.Position != positionA || a.Heading != headingA);
        bool correctedB = counts && (b.Position != positionB || b.Heading != headingB);
        if (correctedA)
        {
            Corrected(a, contact.Depth);
        }

        if (correctedB)
        {
            Corrected(b, contact.Depth);
        }

        handler.OnContact(this, contact);
    }

    // The wedge policy counts a correction the handler's separation made: a fish's or a polygon's
    // (a circle is pushed by whatever presses it and never counts). The first deep one past the
    // policy's allowance in the step rejects the body's move, as RejectMove does.
    private void Corrected(Body b, float depth)
    {
        if (b.IsMoving && b.Kind != BodyKind.Circle && _settling.Wedges(b, depth))
        {
            Touch(b);
            _settling.RejectToStepStart(b);
        }
    }

    /// <summary>The moving bodies the current response has changed or involved so far, in that order (tests).</summary>
    internal BodyId[] ChangedInOrder()
    {
        ReadOnlySpan<Body> movers = _schedule.Planner.MoverBodies;
        var ids = new BodyId[_changed.Count];
        int k = 0;
        foreach (int slot in _changed.Items)
        {
            ids[k++] = movers[slot].Handle;
        }

        return ids;
    }

    // Contacts found together after a response are handled in the order their bodies were first
    // changed or involved (Involve), so before each response its moving bodies are involved in the
    // order the separation moves them: A first, unless A holds still and B does not (then B, which
    // alone is pushed away, first). A body holds still when its move was rejected this step and it
    // is not a circle (a rejected fish is immovable in contacts for the rest of the step; a ball is
    // pushed whatever its move was). Static bodies and the walls are never involved.
    private void InvolveInOrder(Body a, Body b)
    {
        bool aHolds = HoldsStill(a), bHolds = HoldsStill(b);
        if (a.IsMoving && aHolds && b.IsMoving && !bHolds)
        {
            Involve(b);
            Involve(a);
            return;
        }

        Involve(a);
        Involve(b);

        static bool HoldsStill(Body x) => x.Rejected && x.Kind != BodyKind.Circle;

        void Involve(Body x)
        {
            if (x.IsMoving)
            {
                Touch(x);
                Commit(x);
            }
        }
    }

    /// <summary>Tells the handler a body's move was rejected.</summary>
    internal void ReportRejected(BodyId body) => _handler!.OnMoveRejected(this, body);

    // Every body starts the step at its current state; every pair is planned from time 0.
    private void Begin(float seconds, IContactHandler handler)
    {
        if (!(seconds > 0f) || float.IsPositiveInfinity(seconds))
        {
            throw new ArgumentException($"step duration must be positive and finite, got {seconds}", nameof(seconds));
        }

        ArgumentNullException.ThrowIfNull(handler);
        EnsureLoaded();
        _handler = handler;
        _events.BeginStep();
        _settling.BeginStep();
        _contacts.BeginStep();
        _held.BeginStep();
        _schedule.Sampler.Memo.ResetTests();
        Time = 0.0;
        _stepping = true;
        _queryMoversMoved = true;
        _schedule.Begin(seconds);

        // One pass over the movers: each starts the step and is measured for the first plan.
        SweepPlanner planner = _schedule.Planner;
        ReadOnlySpan<Body> movers = planner.MoverBodies;
        for (int m = 0; m < movers.Length; m++)
        {
            movers[m].StartStep();
            planner.Measure(m, 0.0);
        }

        _schedule.PlanStepStart();
        _held.HoldAtStart();
    }

    // Every mover moved to a time of the step and committed there.
    private void MoveAllTo(double time)
    {
        float seconds = _schedule.Seconds;
        foreach (Body body in _schedule.Planner.MoverBodies)
        {
            body.MoveTo(time, seconds);
            body.Rebase(time);
        }

        Time = time;
    }

    // The step's end state becomes the state a rejected move of the next step goes back to; the
    // touches without an answer this step end, reported in the contact cache's order.
    private void End()
    {
        var ended = new EndedTouches(this, _handler!);
        _contacts.EndStep(ref ended);
        _stepping = false;
        Time = 0.0;
        foreach (Body body in _schedule.Planner.MoverBodies)
        {
            body.EndJointTurn();
            body.Rebase(0.0);
            Remember(body);
        }

        _handler = null;
    }

    // Reports each touch that ended to the handler.
    private readonly struct EndedTouches(MotionWorld world, IContactHandler handler) : ContactCache.IEndedSink
    {
        public void Ended(int a, int b) => handler.OnTouchEnded(world, world._bodies[a].Handle, world._bodies[b].Handle);
    }
}
