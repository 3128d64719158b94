using System;
using System.Numerics;

namespace URWPGSim2D.Collision.Motion;

/// <content>Contact events: clusters of hits, the time of first contact, the response, relaxation.</content>
public sealed partial class Stepper
{
    // Rounds of the false-position estimate of the time of first contact before bisection takes over.
    private const int GuessRounds = 3;

    private readonly HitClusters _clusters = new();
    private BodySet _involved = new(0);
    private BodySet _touched = new(0);
    private BodySet _changed = new(0);
    private BodySet _spare = new(0);
    private BodySet _dirty = new(0);
    private BodySet _deferred = new(0);
    private int[] _pending = new int[16];
    private int _pendingCount;

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

    // False-position estimate of a hit's time of first contact (its last free time when unknown).
    private double EstimatedContact(int slot, in Hit hit, double found)
    {
        float closing = ClosingRate(_table.Pair[slot], hit);
        double guess = closing > 0f ? found - (hit.Depth / closing) : _table.LastFree[slot];
        return Math.Clamp(guess, _table.LastFree[slot], found);
    }

    // Between the last time all hits were apart and the sample that found them (checked first
    // unless the hits are known to be apart then): a false-position guess, then bisection until
    // nothing involved moves more than the tolerance inside the bracket.
    private double FirstContact(double free, double hit, bool knownApart)
    {
        float rate = 0f;
        for (int i = 0; i < _sampler.HitCount; i++)
        {
            rate = MathF.Max(rate, _table.Rate[_sampler.HitSlots[i]]);
        }

        if (!knownApart)
        {
            MoveInvolved(free);
            if (AnyHitIntersects())
            {
                return free;
            }
        }

        double lo = free;
        double hi = hit;
        if ((hi - lo) * rate > MotionTolerances.TimeOfImpactTolerance)
        {
            Guess(ref lo, ref hi, rate);
        }
        for (int iteration = 0; iteration < 48 && (hi - lo) * rate > MotionTolerances.TimeOfImpactTolerance; iteration++)
        {
            double mid = 0.5 * (lo + hi);
            MoveInvolved(mid);
            if (AnyHitIntersects())
            {
                hi = mid;
            }
            else
            {
                lo = mid;
            }
        }

        return hi;
    }

    // The deepest hit's depth shrinks at its closing rate, so it reached zero near hi − depth / rate:
    // probe there (exact for translation). While the probe still overlaps, the same estimate from
    // its own depth moves hi on (a few rounds: turning bodies close at a changing rate); once a
    // probe is apart, one more just after it brackets the contact tightly.
    private void Guess(ref double lo, ref double hi, float rate)
    {
        int deepest = 0;
        for (int i = 1; i < _sampler.HitCount; i++)
        {
            deepest = _sampler.HitValues[i].Depth > _sampler.HitValues[deepest].Depth ? i : deepest;
        }

        int slot = _sampler.HitSlots[deepest];
        Hit hit = _sampler.HitValues[deepest];
        for (int round = 0; round < GuessRounds; round++)
        {
            float closing = ClosingRate(_table.Pair[slot], hit);
            if (!(closing > 0f) || rate <= 0f)
            {
                return;
            }

            double guess = hi - (hit.Depth / closing);
            if (!(guess > lo && guess < hi))
            {
                return;
            }

            MoveInvolved(guess);
            if (DeepestHitNow(out slot, out hit))
            {
                hi = guess;
                if ((hi - lo) * rate <= MotionTolerances.TimeOfImpactTolerance)
                {
                    return;
                }

                continue;
            }

            lo = guess;
            double next = lo + (0.5 * MotionTolerances.TimeOfImpactTolerance / rate);
            if (next < hi)
            {
                MoveInvolved(next);
                if (AnyHitIntersects())
                {
                    hi = next;
                }
                else
                {
                    lo = next;
                }
            }

            return;
        }
    }

    // The deepest of the event's pairs that overlaps now, if any.
    private bool DeepestHitNow(out int slot, out Hit deepest)
    {
        slot = -1;
        deepest = default;
        for (int i = 0; i < _sampler.HitCount; i++)
        {
            PlannedPair pair = _table.Pair[_sampler.HitSlots[i]];
            Hit hit = _sampler.Memo.DetectIfNear(_bodies[pair.A], _bodies[pair.B]);
            if (hit.Depth > MotionTolerances.ContactSlop && hit.Depth > deepest.Depth)
            {
                slot = _sampler.HitSlots[i];
                deepest = hit;
            }
        }

        return slot >= 0;
    }

    private bool AnyHitIntersects()
    {
        for (int i = 0; i < _sampler.HitCount; i++)
        {
            PlannedPair pair = _table.Pair[_sampler.HitSlots[i]];
            if (_sampler.Memo.DetectIfNear(_bodies[pair.A], _bodies[pair.B]).Depth > MotionTolerances.ContactSlop)
            {
                return true;
            }
        }

        return false;
    }

    // How fast the two bodies close along the hit's normal at its action point, mm per whole step (positive when approaching).
    private float ClosingRate(in PlannedPair pair, in Hit hit)
    {
        Vector2 a = PointVelocity(_bodies[pair.A], hit.Point);
        Vector2 b = pair.MoverB >= 0 ? PointVelocity(_bodies[pair.B], hit.Point) : Vector2.Zero;
        return -Vector2.Dot(a - b, hit.Normal) * _planner.Seconds;
    }

    private static Vector2 PointVelocity(Body body, Vector2 point)
    {
        Vector2 r = point - body.Position;
        return body.Velocity + (body.AngularVelocity * new Vector2(-r.Y, r.X));
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
