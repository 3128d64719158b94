namespace URWPGSim2D.Collision.Benchmarks.Scaling;

/// <summary>
/// The crowd scene of <see cref="ScalingBenchmarks"/> with the motion world's broad phase brute force
/// (every pair of boxes tested), for 100, 1,000 and 10,000 fish and balls: the reference the grid
/// is measured against (both give the same match, tested). Not run at 30,000 (seconds a cycle).
/// Like <see cref="ScalingBenchmarks"/>, the JIT is warmed first, and every iteration builds the
/// scene afresh, plays its first 20 cycles unmeasured and measures cycles 20 to 29, one a call.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
[InvocationCount(MeasuredCycles)]
public class BruteForceScalingBenchmarks
{
    private const int WarmCycles = 20;
    private const int MeasuredCycles = 10;
    private Match _brute = null!;

    /// <summary>Fish and balls in the scene.</summary>
    [Params(100, 1_000, 10_000)]
    public int Objects { get; set; }

    /// <summary>Warms the JIT on a 1,000-body crowd (see <see cref="JitWarmUp"/>).</summary>
    [GlobalSetup]
    public void WarmUp()
    {
        Match warm = MatchBuilder.Build(CrowdScenario.Create(1_000), broadPhase: BroadPhaseKind.BruteForce);
        JitWarmUp.Until(warm.Step);
    }

    /// <summary>Builds the scene and plays its first 20 cycles.</summary>
    [IterationSetup]
    public void Setup()
    {
        _brute = MatchBuilder.Build(CrowdScenario.Create(Objects), broadPhase: BroadPhaseKind.BruteForce);
        for (int i = 0; i < WarmCycles; i++)
        {
            _brute.Step();
        }
    }

    /// <summary>One cycle, brute-force broad phase.</summary>
    [Benchmark]
    public void BruteForce() => _brute.Step();
}
