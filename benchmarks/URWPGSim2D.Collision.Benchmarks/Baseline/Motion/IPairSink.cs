namespace URWPGSim2D.Collision.Benchmarks.Baseline.Motion;

/// <summary>Receives the candidate pairs the <see cref="SweepPlanner"/> finds.</summary>
internal interface IPairSink
{
    /// <summary>One candidate pair; <paramref name="rate"/> is the most the two move relative to each other over the whole step, mm.</summary>
    void Add(in PlannedPair pair, float rate);
}
