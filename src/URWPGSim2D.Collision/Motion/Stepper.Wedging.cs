using System;
using System.Numerics;

namespace URWPGSim2D.Collision.Motion;

/// <content>
/// Wedged bodies and rejected moves, in one place. A body is wedged when the stepper sees it in many
/// events this step, or in several in a row at one time (pushed back and forth between two
/// obstacles), or when the caller's response says so (<see cref="RejectMove"/>). A wedged body's
/// hits that cannot tunnel before the step ends are left to the end of the step; there, a body
/// left inside another by more than the guarantee allows, or a wedged one still overlapping after
/// settling, has its move rejected. Rejecting a move, whoever decides it, is one thing: the body
/// goes back to where it started the step (pose and joints), at rest, and the handler hears of it.
/// </content>
public sealed partial class Stepper
{
    private BodySet _deferred = new(0);

    /// <summary>
    /// Rejects a moving body's move in the current step, from a handler (a response that finds the
    /// body wedged): it goes back to where it began the step (its pose and joints at the end of the
    /// previous step, or where it was last placed between steps), at rest (own velocity and drift
    /// zero), and <see cref="IContactHandler.OnMoveRejected"/> is called, as for a move the stepper
    /// rejects itself. While <see cref="Settle"/> runs after a step, the move rejected is that
    /// step's. The body stays there for the rest of the step unless moved again.
    /// </summary>
    /// <param name="body">The body's id.</param>
    /// <exception cref="ArgumentException">The body does not move, or no step (or <see cref="Settle"/>) is running.</exception>
    public void RejectMove(int body)
    {
        Body b = Moving(body, null, nameof(body));
        if (!_stepping)
        {
            throw new ArgumentException($"body {body}: a move can be rejected only from a handler, while a step or Settle runs", nameof(body));
        }

        Touch(b);
        MoveBack(b, b.StepStartPosition, b.StepStartHeading, b.StepStartJoint1, b.StepStartJoint2, b.StepStartJoint3, stamp: false);
    }

    // A hit of a wedged body that cannot tunnel before the step ends is left to the end of the step
    // (settling, then a rejected move if it is still deep): a body wedged between two obstacles
    // would otherwise be pushed from one into the other at every sample.
    internal bool Deferred(in PlannedPair pair, int slot, double time)
    {
        bool busy = Wedged(_planner.MoverBodies[pair.MoverA]) || (pair.MoverB >= 0 && Wedged(_planner.MoverBodies[pair.MoverB]));
        if (!busy || _table.Rate[slot] * (1.0 - time) > pair.Limit)
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

    // Many events this step, or several in a row at one time (pushed back and forth in place).
    private static bool Wedged(Body body) =>
        body.Events >= MotionTolerances.EventsBeforeDeferring || body.EventsInPlace >= MotionTolerances.EventsInPlaceBeforeDeferring;

    // A body left inside another by more than the guarantee allows goes back to where it ended the
    // previous step, at rest; the bodies it lands in are checked in turn (the previous step's end
    // was free, so this ends). Returns the deepest overlap left.
    // A body whose contacts were left to the end of the step (it is wedged) is rejected as soon as it
    // still overlaps after settling.
    private float RejectOverlapping(float deepest)
    {
        if (deepest <= MotionTolerances.RejectOverlap && (_deferred.Count == 0 || deepest <= MotionTolerances.ContactSlop))
        {
            return deepest;
        }

        BodySet check = _touched;
        BodySet rejected = _involved;
        rejected.Clear();
        while (true)
        {
            CollectPairsOf(check);
            _changed.Clear();
            foreach (ref readonly var pair in _collector.Pairs)
            {
                Body a = _bodies[pair.A], b = _bodies[pair.B];
                float depth = _sampler.Memo.DetectIfNear(a, b).Depth;
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

            if (_changed.Count == 0)
            {
                break;
            }

            Union(_touched, _changed);
            check = _spare;
            check.Clear();
            Union(check, _changed);
        }

        CollectPairsOf(_touched);
        return Deepest(_collector.Pairs);
    }

    // The end of the step rejects a body once.
    private void Reject(Body body, BodySet rejected)
    {
        if (rejected.Marks[body.Slot])
        {
            return;
        }

        rejected.Add(body.Slot);
        _changed.Add(body.Slot);
        MoveBack(body, body.StartPosition, body.StartHeading, body.StartJoint1, body.StartJoint2, body.StartJoint3, stamp: true);
    }

    // The one way a move is rejected: back to a start pose and joints, at rest, moving on from there;
    // the handler hears of it. The shape counts as changed when the joints change (always, at the
    // end of a step: remembered tests of the body are not reused).
    private void MoveBack(Body body, Vector2 position, float heading, float joint1, float joint2, float joint3, bool stamp)
    {
        RejectedMoves++;
        body.Position = position;
        body.Heading = heading;
        if (stamp || body.Joint1 != joint1 || body.Joint2 != joint2 || body.Joint3 != joint3)
        {
            (body.Joint1, body.Joint2, body.Joint3) = (joint1, joint2, joint3);
            body.ShapeStamp++;
        }

        body.Stop();
        body.Invalidate();
        body.Rebase(Time);
        _handler!.OnMoveRejected(this, body.Id);
    }
}
