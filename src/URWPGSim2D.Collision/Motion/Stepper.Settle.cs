using System;

namespace URWPGSim2D.Collision.Motion;

/// <content>The end of a step: overlaps resolved without motion, measuring.</content>
public sealed partial class Stepper
{
    private readonly PairCollector _collector = new();
    private BodySet _spare = new(0);

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
        Time = 0.0;
        RejectedMoves = 0;
        _touched.Clear();
        for (int m = 0; m < _planner.Movers; m++)
        {
            _touched.Add(m);
        }

        LeftoverOverlap = RejectOverlapping(SettleTouched());
        _stepping = false;
        foreach (Body body in _planner.MoverBodies)
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
        _collector.Clear();
        _planner.PlanAll(1.0, _collector);
        return Deepest(_collector.Pairs);
    }

    private void MoveAllTo(double time)
    {
        float seconds = _planner.Seconds;
        foreach (Body body in _planner.MoverBodies)
        {
            body.MoveTo(time, seconds);
            body.Rebase(time);
        }

        Time = time;
    }

    // Up to SettlePasses passes over the pairs of the bodies that took part in contacts this step:
    // overlaps go to the handler and the bodies that moved are checked again; returns the deepest
    // overlap left among them. When the first pass finds nothing to resolve (the usual case: the
    // events left every pair apart), nothing moved and its depths are the answer: the pairs are not
    // tested a second time.
    private float SettleTouched()
    {
        BodySet current = _touched;
        BodySet next = _spare;
        for (int pass = 0; pass < MotionTolerances.SettlePasses && current.Count > 0; pass++)
        {
            next.Clear();
            _changed.Clear();
            CollectPairsOf(current);
            float quiet = 0f;
            foreach (ref readonly var pair in _collector.Pairs)
            {
                Body a = _bodies[pair.A], b = _bodies[pair.B];
                Hit hit = _sampler.Memo.DetectIfNear(a, b);
                if (hit.Depth > MotionTolerances.ContactSlop)
                {
                    _handler!.OnContact(this, new Contact(pair.A, pair.B, _sampler.Memo.Detect(a, b), Time));
                    Mark(next, pair);
                }
                else
                {
                    quiet = MathF.Max(quiet, hit.Depth);
                }
            }

            foreach (int m in _changed.Items)
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
            next = current == _spare ? _involved : _spare;
        }

        CollectPairsOf(_touched);
        return Deepest(_collector.Pairs);
    }

    private void CollectPairsOf(BodySet set)
    {
        _collector.Clear();
        _planner.PlanFor(set.Items, set.Marks, 1.0, _collector);
    }

    private float Deepest(ReadOnlySpan<PlannedPair> pairs)
    {
        float deepest = 0f;
        foreach (ref readonly var pair in pairs)
        {
            deepest = MathF.Max(deepest, _sampler.Memo.DetectIfNear(_bodies[pair.A], _bodies[pair.B]).Depth);
        }

        return deepest;
    }

    private static void Union(BodySet into, BodySet from)
    {
        foreach (int m in from.Items)
        {
            into.Add(m);
        }
    }
}
