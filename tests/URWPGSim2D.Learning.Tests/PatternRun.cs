namespace URWPGSim2D.Learning.Tests;

/// <summary>A batch reset from seeds 1, 2, … and stepped with actions of a fixed pattern, measuring what each step allocates.</summary>
internal sealed class PatternRun
{
    private readonly float[] _observations;
    private readonly float[] _rewards;
    private readonly int[] _actions;

    public PatternRun(MatchBatch batch)
    {
        Batch = batch;
        _observations = new float[batch.Count * batch.ObservationSize];
        _rewards = new float[batch.Count];
        Terminated = new bool[batch.Count];
        Truncated = new bool[batch.Count];
        _actions = new int[batch.Count * batch.ActionSize];
        var seeds = new ulong[batch.Count];
        for (int i = 0; i < seeds.Length; i++)
        {
            seeds[i] = (ulong)i + 1;
        }

        batch.Reset(seeds, _observations);
    }

    public MatchBatch Batch { get; }

    public bool[] Terminated { get; }

    public bool[] Truncated { get; }

    /// <summary>Plays step <paramref name="step"/> (0-based) of the pattern; returns the bytes the batch's step allocated.</summary>
    public long Step(int step)
    {
        for (int j = 0; j < _actions.Length; j++)
        {
            _actions[j] = ((step * 7) + (j * 3)) % 16;
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        Batch.Step(_actions, _observations, _rewards, Terminated, Truncated);
        return GC.GetAllocatedBytesForCurrentThread() - before;
    }
}
