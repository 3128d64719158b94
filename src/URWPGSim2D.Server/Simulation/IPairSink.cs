namespace URWPGSim2D.Server.Simulation;

/// <summary>Receives the candidate pairs the <see cref="SweepPlanner"/> finds.</summary>
internal interface IPairSink
{
    /// <summary>
    /// One candidate pair; <paramref name="moverA"/> and <paramref name="moverB"/> are its movers
    /// (fish i = i, ball j = fish count + j; −1 for a static body or a wall), <paramref name="rate"/>
    /// the most the two move relative to each other per unit of cycle fraction, mm.
    /// </summary>
    void Add(in CandidatePair pair, int moverA, int moverB, float rate);
}
