using System;

namespace URWPGSim2D.Collision.Motion;

/// <content>Sampling the pairs on their own clocks (see <see cref="PairSampler"/>): planning a pair and its first sample.</content>
public sealed partial class Stepper
{
    private const int Ticks = TickQueue.Ticks;

    private readonly PairSampler _sampler = new();
    private readonly Scheduler _scheduler;

    private void MovePair(in PlannedPair p, double time) => PairSampler.MovePair(_bodies, p, time, _planner.Seconds);

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
                if (owner._sampler.Memo.Detect(a, b).Depth > MotionTolerances.ContactSlop)
                {
                    owner.AddPending(slot);
                    return;
                }

                apart = true;
            }

            table.ApartAtLastFree[slot] = apart;
            if (time < 1.0)
            {
                owner._sampler.Schedule(table, slot, time, gap);
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
        public static double Interval(float limit, float rate)
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
