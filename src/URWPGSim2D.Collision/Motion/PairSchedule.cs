using System.Collections.Generic;
using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The stage that owns a step's candidate pairs and when each is next sampled: the sweep planner
/// over the broad phase (<see cref="SweepPlanner"/>), the table of planned pairs
/// (<see cref="PairTable"/>), and the event loop's sampler (its queue of sample times, the hits of
/// the current sample, the remembered exact tests). At the start of a step every pair is planned
/// from time 0 and stored with its sampling interval; the other stages read and change a pair
/// through the table's methods and plan bodies again through <see cref="Planner"/>.
/// </summary>
internal sealed class PairSchedule
{
    private const int Ticks = TickQueue.Ticks;

    private readonly List<Body> _bodies;
    private readonly Recorder _recorder;

    /// <summary>Creates the stage over a broad phase and the world's bodies (by id).</summary>
    public PairSchedule(IBroadPhase broadPhase, List<Body> bodies)
    {
        Planner = new SweepPlanner(broadPhase);
        _bodies = bodies;
        _recorder = new Recorder(this);
    }

    /// <summary>The candidate pairs of the rest of the step, through the broad phase.</summary>
    public SweepPlanner Planner { get; }

    /// <summary>The planned pairs of the step.</summary>
    public PairTable Table { get; } = new(0);

    /// <summary>The event loop's sampler: its queue, the current sample's hits, the remembered exact tests.</summary>
    public PairSampler Sampler { get; } = new();

    /// <summary>Duration of the step, s.</summary>
    public float Seconds => Planner.Seconds;

    /// <summary>Room for a busy step of a world of <paramref name="movers"/> movers, in pairs.</summary>
    public static int ReservedPairs(int movers) => (8 * movers) + 64;

    /// <summary>Takes a new set of bodies (allocates only here): room for a busy step up front, so that a crowd does not find a new largest step now and then.</summary>
    public void Load(Body[] movers, Body[] statics, Body? walls)
    {
        Planner.Load(movers, statics, walls);
        Table.Resize(movers.Length);
        Table.Reserve(ReservedPairs(movers.Length));
        Sampler.Reserve(movers.Length);
    }

    /// <summary>Starts a step of <paramref name="seconds"/>: no pairs, no queue entries. The movers are then measured from time 0 (<see cref="SweepPlanner.Measure"/>) and planned (<see cref="PlanStepStart"/>).</summary>
    public void Begin(float seconds)
    {
        Planner.Seconds = seconds;
        Table.Clear();
        Sampler.BeginStep();
    }

    /// <summary>Every pair planned from time 0, the movers as measured there, with its sampling interval (not yet scheduled).</summary>
    public void PlanStepStart() => Planner.PlanMeasured(_recorder);

    /// <summary>Places both bodies of a pair at a step time (a static partner stays).</summary>
    public void MovePair(in PlannedPair p, double time) => PairSampler.MovePair(_bodies, p, time, Planner.Seconds);

    /// <summary>Largest power of two (a fraction of the step, at least 1 / <see cref="TickQueue.Ticks"/>) in which the pair moves at most its limit.</summary>
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

    // The first plan of a step: each pair is stored with its sampling interval; the islands schedule their pairs' samples.
    private sealed class Recorder(PairSchedule owner) : IPairSink
    {
        public void Add(in PlannedPair pair, float rate) => owner.Table.Add(pair, rate, Interval(pair.Limit, rate), 0.0);
    }
}
