using System;

namespace URWPGSim2D.Collision.Motion;

/// <content>Sampling the pairs on their own clocks: which are due, testing them, when next.</content>
public sealed partial class Stepper
{
    private const int Ticks = TickQueue.Ticks;

    private readonly Scheduler _scheduler;
    private int[] _due = new int[256];
    private int _dueCount;
    private int[] _hitSlots = new int[64];
    private Hit[] _hitValues = new Hit[64];
    private int _hitCount;
    private float _deepestAtEnd;

    // The live entries of a sample time; returns their number.
    private int TakeDue(double time)
    {
        _dueCount = 0;
        int first = _queue.Take(time);
        for (int node = first; node >= 0; node = _queue.Next(node))
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

        _queue.Recycle(first);
        return _dueCount;
    }

    // Tests every due pair at the time: a pair whose bounds are apart is not tested exactly and waits
    // until it could touch; apart pairs are scheduled again, overlapping ones become hits.
    private void SampleDue(double time)
    {
        for (int i = 0; i < _dueCount; i++)
        {
            MovePair(_table.Pair[_due[i]], time);
        }

        _hitCount = 0;
        for (int i = 0; i < _dueCount; i++)
        {
            int slot = _due[i];
            PlannedPair pair = _table.Pair[slot];
            Body a = _bodies[pair.A], b = _bodies[pair.B];
            float gap = PairTest.Gap(a, b);
            Hit hit = gap > 0f ? default : _memo.Detect(a, b);
            if (hit.Depth > MotionTolerances.ContactSlop)
            {
                if (Deferred(pair, slot, time))
                {
                    continue;
                }

                AddHit(slot, hit);
                continue;
            }

            _table.LastFree[slot] = time;
            _table.ApartAtLastFree[slot] = true;
            if (time < 1.0)
            {
                Schedule(slot, time, gap);
            }
            else
            {
                _deepestAtEnd = MathF.Max(_deepestAtEnd, hit.Depth);
            }
        }
    }

    // The next sample: one interval on (the pair cannot pass through itself in an interval), or later
    // when the pair is apart by a gap it cannot close before then (none when it cannot close it in the step).
    private void Schedule(int slot, double time, float gap)
    {
        double next = Grid(time) + _table.Interval[slot];
        if (gap > 0f)
        {
            float rate = _table.Rate[slot];
            double touch = rate > 0f ? time + (gap / rate) : double.PositiveInfinity;
            if (touch >= 1.0)
            {
                return;
            }

            next = Math.Max(next, Math.Floor(touch * Ticks) / Ticks);
        }

        _queue.Push(Math.Min(next, 1.0), slot, _table.Generation[slot]);
    }

    // A hit of a wedged body (many events this step, or several in a row at one time), which cannot tunnel before the step ends,
    // is left to the end of the step (settling, then a rejected move if it is still deep): a body
    // wedged between two obstacles would otherwise be pushed from one into the other at every sample.
    private bool Deferred(in PlannedPair pair, int slot, double time)
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

    // The grid time at or before a time.
    private static double Grid(double time) => Math.Floor(time * Ticks) / Ticks;

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

    private void MovePair(in PlannedPair p, double time)
    {
        float seconds = _planner.Seconds;
        _bodies[p.A].MoveTo(time, seconds);
        if (p.MoverB >= 0)
        {
            _bodies[p.B].MoveTo(time, seconds);
        }
    }

    // Stores a planned pair and schedules its first sample after the plan time. While relaxing
    // (after a contact) a pair whose bounds overlap is tested at once, and one that overlaps is
    // handed back as pending. A pair planned at the very end of the step cannot be sampled any
    // more: unless it is known to be apart, its movers are settled at the end.
    private sealed class Scheduler(Stepper owner) : IPairSink
    {
        public bool Settling;

        public void Add(in PlannedPair pair, float rate)
        {
            var table = owner._table;
            double time = owner.Time;
            int slot = table.Add(pair, rate);
            table.Interval[slot] = Interval(pair.Limit, rate);
            table.LastFree[slot] = time;

            // The partner may sit at another time of the step: both bodies are placed at the plan time.
            owner.MovePair(pair, time);
            Body a = owner._bodies[pair.A], b = owner._bodies[pair.B];
            float gap = PairTest.Gap(a, b);
            bool apart = gap > 0f;
            if (!apart && Settling)
            {
                if (owner._memo.Detect(a, b).Depth > MotionTolerances.ContactSlop)
                {
                    owner.AddPending(slot);
                    return;
                }

                apart = true;
            }

            table.ApartAtLastFree[slot] = apart;
            if (time < 1.0)
            {
                owner.Schedule(slot, time, gap);
            }
            else if (!apart)
            {
                owner._touched.Add(pair.MoverA);
                if (pair.MoverB >= 0)
                {
                    owner._touched.Add(pair.MoverB);
                }
            }
        }

        // Largest power of two (a fraction of the step, at least 1 / Ticks) in which the pair moves at most its limit.
        private static double Interval(float limit, float rate)
        {
            if (!(rate > 0f) || float.IsPositiveInfinity(limit))
            {
                return 1.0;
            }

            double ticks = limit / (double)rate * Ticks;
            if (ticks >= Ticks)
            {
                return 1.0;
            }

            return (ticks < 2.0 ? 1 : 1 << System.Numerics.BitOperations.Log2((uint)ticks)) / (double)Ticks;
        }
    }
}
