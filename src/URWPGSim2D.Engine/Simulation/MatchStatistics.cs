namespace URWPGSim2D.Engine.Simulation;

/// <summary>Running totals of a match for the summary.</summary>
public sealed class MatchStatistics
{
    /// <summary>Cycles played.</summary>
    public int Cycles { get; private set; }

    /// <summary>Sub-steps over all cycles.</summary>
    public long SubSteps { get; private set; }

    /// <summary>Most sub-steps in one cycle.</summary>
    public int MostSubSteps { get; private set; }

    /// <summary>Contact events (times of first contact) over all cycles.</summary>
    public long Events { get; private set; }

    /// <summary>Deepest overlap left at the end of any cycle, mm.</summary>
    public float LargestLeftoverOverlap { get; private set; }

    /// <summary>The cycle that left it (0 if none).</summary>
    public int LargestLeftoverCycle { get; private set; }

    /// <summary>Adds one cycle's figures.</summary>
    public void Record(int cycle, int subSteps, int events, float leftover)
    {
        Cycles++;
        SubSteps += subSteps;
        MostSubSteps = Math.Max(MostSubSteps, subSteps);
        Events += events;
        if (leftover > LargestLeftoverOverlap)
        {
            LargestLeftoverOverlap = leftover;
            LargestLeftoverCycle = cycle;
        }
    }

    /// <summary>Back to no cycle recorded, as new: a match restarted in place.</summary>
    internal void Restart()
    {
        Cycles = 0;
        SubSteps = 0;
        MostSubSteps = 0;
        Events = 0;
        LargestLeftoverOverlap = 0f;
        LargestLeftoverCycle = 0;
    }
}
