using System;

namespace URWPGSim2D.Collision.Motion;

/// <content>Contact events: the hits of a sample in clusters, each event's bodies taken back to its time of first contact (<c>Stepper.FirstContact.cs</c>), the handler's response, then relaxation (<c>Stepper.Relaxation.cs</c>).</content>
public sealed partial class Stepper
{
    private readonly HitClusters _clusters = new();
    private BodySet _involved = new(0);
    private BodySet _touched = new(0);
    private BodySet _changed = new(0);

    // The hits of one sample fall into clusters that share no moving body (a fish pushing a ball
    // here, two balls meeting there): each is its own event, taken in the order of its estimated
    // time of first contact, so one contact does not pull unrelated bodies back in time. A hit whose
    // pair was planned again by an earlier event is left to its new schedule.
    private void HandleHits(double found)
    {
        if (_sampler.HitCount == 0)
        {
            return;
        }

        int count = _sampler.HitCount;
        _clusters.Load(_sampler.HitSlots, _sampler.HitValues, count, _table);
        for (int i = 0; i < count; i++)
        {
            _clusters.Estimate[i] = EstimatedContact(_clusters.Slot[i], _clusters.Value[i], found);
        }

        _clusters.Cluster();
        foreach (int cluster in _clusters.ClustersByTime())
        {
            _sampler.HitCount = 0;
            for (int i = 0; i < count; i++)
            {
                int slot = _clusters.Slot[i];
                if (_clusters.Label[i] == cluster && _table.Alive[slot] && _table.Generation[slot] == _clusters.Generation[i])
                {
                    _sampler.AddHit(slot, _clusters.Value[i]);
                }
            }

            if (_sampler.HitCount > 0)
            {
                HandleEvent(found);
            }
        }
    }

    // One event: its bodies go back to the last time all its pairs were apart, the time of first
    // contact is found, the handler responds there, and the bodies are committed and planned again.
    private void HandleEvent(double found)
    {
        _involved.Clear();
        double lo = found;
        float deepest = 0f;
        for (int i = 0; i < _sampler.HitCount; i++)
        {
            int slot = _sampler.HitSlots[i];
            lo = Math.Min(lo, _table.LastFree[slot]);
            deepest = MathF.Max(deepest, _sampler.HitValues[i].Depth);
            Mark(_involved, _table.Pair[slot]);
        }

        // Each hit sampled apart was apart at its last sample; all were apart at lo if they share it.
        bool apartAtLo = true;
        for (int i = 0; i < _sampler.HitCount; i++)
        {
            apartAtLo &= _table.LastFree[_sampler.HitSlots[i]] == lo && _table.ApartAtLastFree[_sampler.HitSlots[i]];
        }

        bool refine = deepest > MotionTolerances.TimeOfImpactTolerance;
        foreach (int m in _involved.Items)
        {
            Body body = _planner.MoverBodies[m];
            apartAtLo &= body.BaseTime <= lo;
            lo = Math.Max(lo, body.BaseTime);
            refine &= body.Events < MotionTolerances.MaximumEventsPerBody;
        }

        double contact = refine && lo < found ? FirstContact(lo, found, apartAtLo) : found;
        MoveInvolved(contact);
        Time = contact;
        Events++;
        foreach (int m in _involved.Items)
        {
            Body body = _planner.MoverBodies[m];
            body.Events++;
            body.EventsInPlace = body.LastEventTime == contact ? body.EventsInPlace + 1 : 0;
            body.LastEventTime = contact;
            _touched.Add(m);
        }

        _changed.Clear();
        for (int i = 0; i < _sampler.HitCount; i++)
        {

            Respond(_table.Pair[_sampler.HitSlots[i]]);
        }

        Relax();
    }

    // The handler's response to one pair, if it still overlaps.
    private void Respond(in PlannedPair pair)
    {
        Body a = _bodies[pair.A], b = _bodies[pair.B];
        Hit hit = _sampler.Memo.Detect(a, b);
        if (hit.Depth > MotionTolerances.ContactSlop)
        {
            _handler!.OnContact(this, new Contact(pair.A, pair.B, hit, Time));
        }
    }

    private void MoveInvolved(double time)
    {
        float seconds = _planner.Seconds;
        foreach (int m in _involved.Items)
        {
            _planner.MoverBodies[m].MoveTo(time, seconds);
        }
    }

    private static void Mark(BodySet set, in PlannedPair p)
    {
        set.Add(p.MoverA);
        if (p.MoverB >= 0)
        {
            set.Add(p.MoverB);
        }
    }
}
