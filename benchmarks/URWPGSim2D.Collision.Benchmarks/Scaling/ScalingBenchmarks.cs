extern alias baseline;

using BaselineBuilder = baseline::URWPGSim2D.Server.Scenario.MatchBuilder;
using BaselineMatch = baseline::URWPGSim2D.Server.Simulation.Match;

namespace URWPGSim2D.Collision.Benchmarks.Scaling;

/// <summary>
/// One whole cycle of a crowd scene (<see cref="CrowdScenario"/>: fish and balls at the default
/// match's density, the pool growing with the count, fish on fixed random decisions) for 100 to
/// 30,000 fish and balls, the motion world's broad phase a uniform grid, against the frozen baseline
/// (<see cref="BaselineMatch"/>: the same scene played by the whole server of the commit tagged
/// <c>benchmark-baseline</c>, compiled from that tag) measured in the same run. The JIT is warmed
/// first (<see cref="JitWarmUp"/>); every iteration builds the scene afresh and plays its first 20
/// cycles unmeasured (the starting overlaps are resolved in the first ones), then measures cycles
/// 20 to 29, one a call: every iteration, and both methods, time the same cycles (a crowd's cycles
/// grow dearer as it jams, so timing whichever cycles a method happened to reach would compare
/// unlike work). Brute force, the broad phase's reference, is in
/// <see cref="BruteForceScalingBenchmarks"/>.
/// </summary>
[Config(typeof(BaselineConfig))]
[InvocationCount(MeasuredCycles)]
public class ScalingBenchmarks
{
    private const int WarmCycles = 20;
    private const int MeasuredCycles = 10;
    private Match _grid = null!;
    private BaselineMatch _baseline = null!;

    /// <summary>Fish and balls in the scene.</summary>
    [Params(100, 300, 1_000, 3_000, 10_000, 30_000)]
    public int Objects { get; set; }

    /// <summary>Warms the JIT on a 1,000-body crowd (see <see cref="JitWarmUp"/>).</summary>
    [GlobalSetup(Target = nameof(Grid))]
    public void WarmUp()
    {
        Match warm = MatchBuilder.Build(CrowdScenario.Create(1_000));
        JitWarmUp.Until(warm.Step);
    }

    /// <summary>Warms the JIT on a 1,000-body crowd played by the frozen motion stage.</summary>
    [GlobalSetup(Target = nameof(Baseline))]
    public void WarmUpBaseline()
    {
        BaselineMatch warm = BaselineBuilder.Build(baseline::URWPGSim2D.Server.Scenario.CrowdScenario.Create(1_000));
        JitWarmUp.Until(warm.Step);
    }

    /// <summary>Builds the scene and plays its first 20 cycles.</summary>
    [IterationSetup(Target = nameof(Grid))]
    public void Setup()
    {
        _grid = MatchBuilder.Build(CrowdScenario.Create(Objects));
        for (int i = 0; i < WarmCycles; i++)
        {
            _grid.Step();
        }
    }

    /// <summary>Builds the scene for the frozen motion stage and plays its first 20 cycles.</summary>
    [IterationSetup(Target = nameof(Baseline))]
    public void SetupBaseline()
    {
        _baseline = BaselineBuilder.Build(baseline::URWPGSim2D.Server.Scenario.CrowdScenario.Create(Objects));
        for (int i = 0; i < WarmCycles; i++)
        {
            _baseline.Step();
        }
    }

    /// <summary>One cycle, uniform grid broad phase.</summary>
    [Benchmark]
    public void Grid() => _grid.Step();

    /// <summary>One cycle of the same scene with the frozen motion stage.</summary>
    [Benchmark(Baseline = true)]
    public void Baseline() => _baseline.Step();
}
