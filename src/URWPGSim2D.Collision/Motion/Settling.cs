using System.Collections.Generic;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The stage that ends a step: overlaps resolved without motion, wedged bodies and rejected moves,
/// and measuring. It owns the bodies that took part in contacts this step (<see cref="MarkTouched"/>),
/// the wedged bodies whose hits were left to the end, and the count of rejected moves.
/// <para>
/// A body is wedged when the motion world sees it in many events this step, or in several in a row at
/// one time (pushed back and forth between two obstacles), or when the caller's response says so
/// (<see cref="MotionWorld.RejectMove"/>). A wedged body's hits that cannot tunnel before the step
/// ends are left to the end of the step; there, a body left inside another by more than the
/// guarantee allows, or a wedged one still overlapping after settling, has its move rejected.
/// Rejecting a move, whoever decides it, is one thing: the body goes back to where it started the
/// step (pose and joints), at rest, and the handler hears of it.
/// </para>
/// </summary>
internal sealed class Settling
{
    private readonly MotionWorld _world;
    private readonly PairSchedule _schedule;
    private readonly List<Body> _bodies;
    private readonly PairCollector _collector = new();
    private BodySet _touched = new(0);
    private BodySet _deferred = new(0);
    private BodySet _spare = new(0);
    private BodySet _other = new(0);

    /// <summary>Creates the stage over the world and its pair schedule.</summary>
    public Settling(MotionWorld world, PairSchedule schedule, List<Body> bodies)
    {
        _world = world;
        _schedule = schedule;
        _bodies = bodies;
    }

    /// <summary>When a body counts as wedged and its move is rejected (<see cref="MotionWorld.Wedging"/>).</summary>
    public WedgePolicy Policy { get; set; } = new();

    /// <summary>Deepest overlap of any pair at the end of the last step (<see cref="EndStep"/>) or <see cref="SettleAll"/>, mm.</summary>
    public float LeftoverOverlap { get; private set; }

    /// <summary>Bodies whose move was rejected in the current or last step (or <see cref="SettleAll"/>).</summary>
    public int RejectedMoves { get; private set; }

    /// <summary>Sizes the storage for a world of <paramref name="movers"/> movers.</summary>
    public void Load(int movers)
    {
        _collector.Reserve((8 * movers) + 256);
        _touched = new BodySet(movers);
        _deferred = new BodySet(movers);
        _spare = new BodySet(movers);
        _other = new BodySet(movers);
    }

    /// <summary>Starts a step: no body touched, deferred or rejected yet.</summary>
    public void BeginStep()
    {
        RejectedMoves = 0;
        _touched.Clear();
        _deferred.Clear();
    }

    /// <summary>A mover took part in a contact this step (or may still overlap at its end): it is settled at the end.</summary>
    public void MarkTouched(int mover) => _touched.Add(mover);

    /// <summary>
    /// Between steps: every mover's pairs settled without motion, then the moves of bodies still
    /// inside another one rejected (those whose hits the last step left to its end as soon as they
    /// overlap at all). The deepest overlap left is <see cref="LeftoverOverlap"/>.
    /// </summary>
    public void SettleAll()
    {
        RejectedMoves = 0;
        _touched.Clear();
        for (int m = 0; m < _schedule.Planner.Movers; m++)
        {
            _touched.Add(m);
        }

        LeftoverOverlap = RejectOverlapping(SettleTouched(fromPlan: false));
    }

    /// <summary>Deepest overlap among all pairs of bodies now (no motion), mm.</summary>
    public float MeasureOverlap()
    {
        _collector.Clear();
        _schedule.Planner.PlanAll(1.0, _collector);
        return Deepest(_collector.Pairs);
    }

    /// <summary>
    /// The end of a step, every body at its end: the touched bodies settled, then the moves of those
    /// left inside others rejected. <paramref name="deepestAtEnd"/> is the deepest overlap the event
    /// loop found at the end of the step; the deepest left is <see cref="LeftoverOverlap"/>.
    /// </summary>
    public void EndStep(float deepestAtEnd) => LeftoverOverlap = RejectOverlapping(MathF.Max(deepestAtEnd, SettleTouched(fromPlan: true)));

    /// <summary>
    /// Up to <see cref="MotionTolerances.SettlePasses"/> passes over the pairs of the bodies that
    /// took part in contacts this step: overlaps go to the handler and the bodies that moved are
    /// checked again; returns the deepest overlap left among them. When the first pass finds
    /// nothing to resolve (the usual case: the events left every pair apart), nothing moved and its
    /// depths are the answer: the pairs are not tested a second time. At the end of a step
    /// (<paramref name="fromPlan"/>) the first pass takes the pairs from the step's plan
    /// (<see cref="PairSchedule.PlanAtEnd"/>): the same pairs, without asking the broad phase again.
    /// </summary>
    private float SettleTouched(bool fromPlan)
    {
        BodySet current = _touched;
        BodySet next = _spare;
        TestMemo memo = _schedule.Sampler.Memo;
        for (int pass = 0; pass < MotionTolerances.SettlePasses && current.Count > 0; pass++)
        {
            next.Clear();
            _world.ClearChanged();
            if (pass == 0 && fromPlan)
            {
                // Nothing answered yet: the pairs planned this step hold every candidate.
                _collector.Clear();
                _schedule.PlanAtEnd(current.Items, current.Marks, _collector);
            }
            else
            {
                CollectPairsOf(current);
            }

            float quiet = 0f;
            foreach (ref readonly var pair in _collector.Pairs)
            {
                Body a = _bodies[pair.A], b = _bodies[pair.B];
                Hit hit = memo.DetectIfNear(a, b);
                if (hit.Depth > MotionTolerances.ContactSlop)
                {
                    _world.Report(new Contact(a, b, memo.Detect(a, b), _world.Time));
                    next.AddPair(pair);
                }
                else
                {
                    quiet = MathF.Max(quiet, hit.Depth);
                }
            }

            foreach (int m in _world.ChangedBodies)
            {
                next.Add(m);
            }

            if (next.Count == 0)
            {
                if (pass == 0)
                {
                    return quiet;
                }

                break;
            }

            Union(_touched, next);
            current = next;
            next = current == _spare ? _other : _spare;
        }

        CollectPairsOf(_touched);
        return Deepest(_collector.Pairs);
    }

    /// <summary>
    /// A hit of a wedged body that cannot tunnel before the step ends is left to the end of the
    /// step (settling, then a rejected move if it is still deep): a body wedged between two
    /// obstacles would otherwise be pushed from one into the other at every sample.
    /// </summary>
    public bool Deferred(in PlannedPair pair, int slot, double time)
    {
        ReadOnlySpan<Body> movers = _schedule.Planner.MoverBodies;
        bool busy = Wedged(movers[pair.MoverA]) || (pair.MoverB >= 0 && Wedged(movers[pair.MoverB]));
        if (!busy || _schedule.Table.Rate(slot) * (1.0 - time) > pair.Limit)
        {
            return false;
        }

        _touched.Add(pair.MoverA);
        _deferred.Add(pair.MoverA);
        if (pair.MoverB >= 0)
        {
            _touched.Add(pair.MoverB);
            _deferred.Add(pair.MoverB);
        }

        return true;
    }

    /// <summary>
    /// A body left inside another by more than the guarantee allows goes back to where it ended the
    /// previous step, at rest; the bodies it lands in are checked in turn (the previous step's end
    /// was free, so this ends). A body whose contacts were left to the end of the step (it is
    /// wedged) is rejected as soon as it still overlaps after settling. Returns the deepest overlap left.
    /// </summary>
    private float RejectOverlapping(float deepest)
    {
        if (deepest <= MotionTolerances.RejectOverlap && (_deferred.Count == 0 || deepest <= MotionTolerances.ContactSlop))
        {
            return deepest;
        }

        TestMemo memo = _schedule.Sampler.Memo;
        BodySet check = _touched;
        BodySet rejected = _other;
        rejected.Clear();
        while (true)
        {
            CollectPairsOf(check);
            _world.ClearChanged();
            foreach (ref readonly var pair in _collector.Pairs)
            {
                Body a = _bodies[pair.A], b = _bodies[pair.B];
                float depth = memo.DetectIfNear(a, b).Depth;
                if (depth > MotionTolerances.RejectOverlap)
                {
                    Reject(a, rejected);
                    if (pair.MoverB >= 0)
                    {
                        Reject(b, rejected);
                    }
                }
                else if (depth > MotionTolerances.ContactSlop)
                {
                    if (_deferred.Marks[pair.MoverA])
                    {
                        Reject(a, rejected);
                    }

                    if (pair.MoverB >= 0 && _deferred.Marks[pair.MoverB])
                    {
                        Reject(b, rejected);
                    }
                }
            }

            if (_world.ChangedBodies.Length == 0)
            {
                break;
            }

            UnionChanged(_touched);
            check = _spare;
            check.Clear();
            UnionChanged(check);
        }

        CollectPairsOf(_touched);
        return Deepest(_collector.Pairs);
    }

    /// <summary>A response's verdict (<see cref="MotionWorld.RejectMove"/>): the body goes back to where it began the step, at rest.</summary>
    public void RejectToStepStart(Body b) =>
        MoveBack(b, b.StepStartPosition, b.StepStartHeading, b.StepStartJoint1, b.StepStartJoint2, b.StepStartJoint3, stamp: false);

    /// <summary>
    /// Counts a correction of a body by the handler's separation (<see cref="IContactHandler.OnSeparate"/>) at a
    /// contact's depth: true when it is a deep one past the policy's allowance for the step and
    /// the body's move is not rejected yet (the caller rejects it).
    /// </summary>
    public bool Wedges(Body b, float depth) =>
        depth > MotionTolerances.TimeOfImpactTolerance && ++b.Corrections > Policy.CorrectionsBeforeRejecting && !b.Rejected;

    // Many events this step, or several in a row at one time (pushed back and forth in place).
    private bool Wedged(Body body) => Policy.Wedged(body.Events, body.EventsInPlace);

    // The end of the step rejects a body once.
    private void Reject(Body body, BodySet rejected)
    {
        if (rejected.Marks[body.Slot])
        {
            return;
        }

        rejected.Add(body.Slot);
        _world.MarkChanged(body.Slot);
        MoveBack(body, body.StartPosition, body.StartHeading, body.StartJoint1, body.StartJoint2, body.StartJoint3, stamp: true);
    }

    // The one way a move is rejected: back to a start pose and joints, at rest, moving on from there;
    // the handler hears of it. The shape counts as changed when the joints change (always, at the
    // end of a step: remembered tests of the body are not reused).
    private void MoveBack(Body body, Vector2 position, float heading, float joint1, float joint2, float joint3, bool stamp)
    {
        RejectedMoves++;
        body.Rejected = true;
        body.Position = position;
        body.Heading = heading;
        if (stamp || body.Joint1 != joint1 || body.Joint2 != joint2 || body.Joint3 != joint3)
        {
            (body.Joint1, body.Joint2, body.Joint3) = (joint1, joint2, joint3);
            body.ShapeStamp++;
        }

        body.Stop();
        body.EndJointTurn();
        body.Invalidate();
        body.Rebase(_world.Time);
        _world.ReportRejected(body.Handle);
    }

    private void CollectPairsOf(BodySet set)
    {
        _collector.Clear();
        _schedule.Planner.PlanFor(set.Items, set.Marks, 1.0, _collector);
    }

    private float Deepest(ReadOnlySpan<PlannedPair> pairs)
    {
        TestMemo memo = _schedule.Sampler.Memo;
        float deepest = 0f;
        foreach (ref readonly var pair in pairs)
        {
            deepest = MathF.Max(deepest, memo.DetectIfNear(_bodies[pair.A], _bodies[pair.B]).Depth);
        }

        return deepest;
    }

    private void UnionChanged(BodySet into)
    {
        foreach (int m in _world.ChangedBodies)
        {
            into.Add(m);
        }
    }

    private static void Union(BodySet into, BodySet from)
    {
        foreach (int m in from.Items)
        {
            into.Add(m);
        }
    }
}
