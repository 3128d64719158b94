namespace URWPGSim2D.Collision.Benchmarks.Scaling;

/// <summary>
/// Whole cycles of the crowd scene of <see cref="ScalingBenchmarks"/> at 1,000 and 10,000 fish and
/// balls, its motion world on one thread (the baseline) and on two (<c>run --threads 2</c>: the
/// islands sampled on two threads up to their first contact); both play the same match, tested.
/// The JIT is warmed first (<see cref="JitWarmUp"/>); every iteration builds the scene afresh and
/// plays its first 20 cycles unmeasured, then measures cycles 20 to 29, one a call: both methods
/// time the same cycles (a crowd's cycles grow dearer as it jams, so timing whichever cycles each
/// method happened to reach would compare unlike work).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
[InvocationCount(MeasuredCycles)]
public class ThreadsBenchmarks
{
    private const int WarmCycles = 20;
    private const int MeasuredCycles = 10;
    private Match _one = null!;
    private Match _two = null!;

    /// <summary>Fish and balls in the scene.</summary>
    [Params(1_000, 10_000)]
    public int Objects { get; set; }

    /// <summary>Warms the JIT on a 1,000-body crowd on one thread (see <see cref="JitWarmUp"/>).</summary>
    [GlobalSetup(Target = nameof(OneThread))]
    public void WarmUpOne() => WarmUp(1_000, 1);

    /// <summary>Warms the JIT on a 3,000-body crowd on two threads (enough moving bodies to use them).</summary>
    [GlobalSetup(Target = nameof(TwoThreads))]
    public void WarmUpTwo() => WarmUp(3_000, 2);

    /// <summary>Builds the scene for one thread and plays its first 20 cycles.</summary>
    [IterationSetup(Target = nameof(OneThread))]
    public void SetupOne() => _one = Warm(1);

    /// <summary>Builds the scene for two threads and plays its first 20 cycles.</summary>
    [IterationSetup(Target = nameof(TwoThreads))]
    public void SetupTwo() => _two = Warm(2);

    /// <summary>One cycle, the motion world on the calling thread.</summary>
    [Benchmark(Baseline = true)]
    public void OneThread() => _one.Step();

    /// <summary>One cycle, the motion world's islands on two threads.</summary>
    [Benchmark]
    public void TwoThreads() => _two.Step();

    private static void WarmUp(int objects, int threads)
    {
        Match warm = MatchBuilder.Build(CrowdScenario.Create(objects));
        warm.Motion.Threads = threads;
        JitWarmUp.Until(warm.Step);
    }

    private Match Warm(int threads)
    {
        var match = MatchBuilder.Build(CrowdScenario.Create(Objects));
        match.Motion.Threads = threads;
        for (int i = 0; i < WarmCycles; i++)
        {
            match.Step();
        }

        return match;
    }
}
