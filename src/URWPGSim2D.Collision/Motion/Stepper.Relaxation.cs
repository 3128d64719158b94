using System;

namespace URWPGSim2D.Collision.Motion;

/// <content>
/// Relaxation after a contact event: the bodies the response changed are committed at the contact
/// time and planned again; pairs that overlap right away (a ball squeezed between two fish) are
/// responded to at once, a few passes over, before the rest is sampled as usual.
/// </content>
public sealed partial class Stepper
{
    private BodySet _dirty = new(0);
    private int[] _pending = new int[16];
    private int _pendingCount;

    // Commits the event's bodies (and any the handler changed) at the contact time and plans their
    // pairs again. A response can push a body into a third one (a ball squeezed between two fish):
    // pairs that overlap right away are responded to at once, a few passes over; while such a
    // cascade lasts, the bodies it moves are checked against the pairs already planned for them
    // (no broad phase), and once it is quiet they are planned again, once. What is left is sampled
    // as usual.
    private void Relax()
    {
        int pass = 0;
        CommitChanged(_involved);
        Replan(pass++);
        while (_pendingCount > 0)
        {
            _involved.Clear();
            RespondPending();
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

                RespondPending();
            }

            Replan(pass);
        }
    }

    // The bodies the handler changed join the event (and the step's touched bodies), committed at the contact time.
    private void CommitChanged(BodySet into)
    {
        foreach (int m in _changed.Items)
        {
            into.Add(m);
            _involved.Add(m);
            _touched.Add(m);
        }

        _changed.Clear();
        foreach (int m in into.Items)
        {
            _planner.MoverBodies[m].Rebase(Time);
        }
    }

    // Plans every pair of the involved bodies again; while passes are left, pairs that overlap now are pending.
    private void Replan(int pass)
    {
        foreach (int m in _involved.Items)
        {
            _planner.MoverBodies[m].Rebase(Time);
            _table.RemoveAllOf(m);
        }

        _pendingCount = 0;
        _scheduler.Settling = pass < MotionTolerances.RelaxationPasses;
        _planner.PlanFor(_involved.Items, _involved.Marks, Time, _scheduler);
        _scheduler.Settling = false;
    }

    // The pairs already planned for the given bodies that overlap now become pending (each pair once).
    private void ScanPlanned(BodySet bodies)
    {
        _pendingCount = 0;
        int stamp = _table.NextStamp();
        foreach (int m in bodies.Items)
        {
            for (int edge = _table.FirstEdge(m); edge >= 0; edge = _table.NextEdge(edge))
            {
                int slot = edge >> 1;
                if (_table.Stamp[slot] == stamp)
                {
                    continue;
                }

                _table.Stamp[slot] = stamp;
                PlannedPair pair = _table.Pair[slot];
                MovePair(pair, Time);
                Body a = _bodies[pair.A], b = _bodies[pair.B];
                if (_sampler.Memo.DetectIfNear(a, b).Depth > MotionTolerances.ContactSlop)
                {
                    AddPending(slot);
                }
            }
        }
    }

    // The handler's response to each pending pair; their bodies join the event.
    private void RespondPending()
    {
        for (int i = 0; i < _pendingCount; i++)
        {
            Mark(_involved, _table.Pair[_pending[i]]);
        }

        for (int i = 0; i < _pendingCount; i++)
        {
            Respond(_table.Pair[_pending[i]]);
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
}
