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
    private readonly IndexList _partners = new(64);

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

    /// <summary>The most pairs a world can have planned at once: every two movers, and every mover with every static body and the walls (<paramref name="others"/>).</summary>
    public static int MostPairs(int movers, int others) => (int)Math.Min(int.MaxValue, ((long)movers * (movers - 1) / 2) + ((long)movers * others));

    /// <summary>The pair slots a world keeps room for: a busy step's (<see cref="ReservedPairs"/>), never more than it can have at once (<see cref="MostPairs"/>).</summary>
    public static int PairRoom(int movers, int others) => Math.Min(ReservedPairs(movers), MostPairs(movers, others));

    /// <summary>The pair slots the loaded world keeps room for (<see cref="PairRoom"/>).</summary>
    public int Room { get; private set; }

    /// <summary>Takes a new set of bodies (allocates only here): room for a busy step up front, so that a crowd does not find a new largest step now and then.</summary>
    public void Load(Body[] movers, Body[] statics, Body? walls)
    {
        Planner.Load(movers, statics, walls);
        Table.Resize(movers.Length);
        Room = PairRoom(movers.Length, statics.Length + (walls is null ? 0 : 1));
        Table.Reserve(Room);
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

    /// <summary>
    /// The candidate pairs of the given movers at the end of the step, the same pairs in the same
    /// order as <see cref="SweepPlanner.PlanFor"/> at time 1 reports them, taken from each mover's
    /// planned pairs instead of the broad phase: every pair whose swept circles meet is planned
    /// (each re-plan planned its body's pairs again), and a mover's circle at the end of the step
    /// lies within its swept circle. Valid while no body has left its planned motion (before the
    /// end of the step answers any contact); the broad phase keeps the movers' boxes of the step,
    /// which still hold them.
    /// </summary>
    public void PlanAtEnd(ReadOnlySpan<int> movers, ReadOnlySpan<bool> isListed, IPairSink sink)
    {
        foreach (int m in movers)
        {
            Planner.Measure(m, 1.0);
        }

        int count = Planner.Movers;
        foreach (int m in movers)
        {
            _partners.Clear();
            for (int edge = Table.FirstEdge(m); edge >= 0; edge = Table.NextEdge(edge))
            {
                ref readonly PlannedPair pair = ref Table.Pair(edge >> 1);
                int other = pair.MoverA == m ? pair.MoverB : pair.MoverA;
                if (other >= 0)
                {
                    _partners.Add(other);
                }
                else if (_bodies[pair.B] is { Kind: BodyKind.Static } body)
                {
                    _partners.Add(count + body.Slot); // the walls are offered by the planner itself
                }
            }

            _partners.SortFrom(0);
            Planner.Offer(m, _partners.Items, isListed, sink);
        }
    }

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
