extern alias baseline;

using BaselineBuilder = baseline::URWPGSim2D.Server.Scenario.MatchBuilder;
using BaselineMatch = baseline::URWPGSim2D.Server.Simulation.Match;

namespace URWPGSim2D.Collision.Benchmarks.Server;

/// <summary>
/// One cycle of the embedded default match (4 fish, 9 balls, 4 obstacles, 4 goal blocks, walls),
/// 500 cycles into the match so that fish and balls are in play, against the frozen baseline
/// (<see cref="BaselineMatch"/>: the same match played by the whole server of the commit tagged
/// <c>benchmark-baseline</c>, compiled from that tag) measured in the same run. <see cref="Detection"/> is the detection alone: broad phase and
/// every candidate pair's exact test at the state of cycle 500 (no motion, no response).
/// <see cref="Cycle"/> is the whole 100 ms cycle: strategies, locomotion, sub-stepped motion with
/// times of first contact and responses, rules, reported per cycle over cycles 500 to 1,499: each
/// iteration rebuilds the match, plays it to cycle 500 (not measured) and then plays those 1,000
/// cycles, so every iteration measures the same work (the cost of a cycle depends much on the
/// phase of the match). <see cref="CycleSeeds"/> is the same whole cycle over the first 1,000 cycles
/// of the default match at seeds 1 to 8: once a change alters the motion by rounding-sized amounts
/// the two stages play different matches from then on (the match is chaotic: a fish wedged against
/// an obstacle for hundreds of cycles in one and not in the other), so one phase of one match
/// measures which match each happened to play more than the code; eight whole matches average that out.
/// </summary>
[Config(typeof(BaselineConfig))]
public class DefaultMatchCycleBenchmarks
{
    private const int WarmCycles = 500;
    private const int MeasuredCycles = 1_000;
    private const int Seeds = 8;
    private const int SeedCycles = 1_000;
    private Match _match = null!;
    private BaselineMatch _baseline = null!;
    private readonly Match[] _seedMatches = new Match[Seeds];
    private readonly BaselineMatch[] _seedBaselines = new BaselineMatch[Seeds];

    /// <summary>Builds the default match and plays its first 500 cycles.</summary>
    [GlobalSetup(Target = nameof(Detection))]
    [IterationSetup(Target = nameof(Cycle))]
    public void Setup()
    {
        _match = MatchBuilder.Build(DefaultScenario.Load());
        for (int i = 0; i < WarmCycles; i++)
        {
            _match.Step();
        }
    }

    /// <summary>Builds the default match for the frozen motion stage and plays its first 500 cycles.</summary>
    [GlobalSetup(Target = nameof(DetectionBaseline))]
    [IterationSetup(Target = nameof(CycleBaseline))]
    public void SetupBaseline()
    {
        _baseline = BaselineBuilder.Build(baseline::URWPGSim2D.Server.Scenario.DefaultScenario.Load());
        for (int i = 0; i < WarmCycles; i++)
        {
            _baseline.Step();
        }
    }

    /// <summary>Builds the default match at seeds 1 to 8.</summary>
    [IterationSetup(Target = nameof(CycleSeeds))]
    public void SetupSeeds()
    {
        for (int i = 0; i < Seeds; i++)
        {
            _seedMatches[i] = MatchBuilder.Build(DefaultScenario.Load(), seed: (ulong)(i + 1));
        }
    }

    /// <summary>Builds the default match at seeds 1 to 8 for the frozen motion stage.</summary>
    [IterationSetup(Target = nameof(CycleSeedsBaseline))]
    public void SetupSeedsBaseline()
    {
        for (int i = 0; i < Seeds; i++)
        {
            _seedBaselines[i] = BaselineBuilder.Build(baseline::URWPGSim2D.Server.Scenario.DefaultScenario.Load(), seed: (ulong)(i + 1));
        }
    }

    /// <summary>Cycles 0 to 999 of the default match at seeds 1 to 8, per cycle.</summary>
    [Benchmark(OperationsPerInvoke = Seeds * SeedCycles)]
    [InvocationCount(1, 1)]
    [BenchmarkCategory("cycle, 8 seeds")]
    public void CycleSeeds()
    {
        foreach (Match match in _seedMatches)
        {
            for (int i = 0; i < SeedCycles; i++)
            {
                match.Step();
            }
        }
    }

    /// <summary>The same matches with the frozen motion stage, per cycle.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Seeds * SeedCycles)]
    [InvocationCount(1, 1)]
    [BenchmarkCategory("cycle, 8 seeds")]
    public void CycleSeedsBaseline()
    {
        foreach (BaselineMatch match in _seedBaselines)
        {
            for (int i = 0; i < SeedCycles; i++)
            {
                match.Step();
            }
        }
    }

    /// <summary>Broad phase plus the exact test of every candidate pair; returns the deepest overlap.</summary>
    [Benchmark]
    [BenchmarkCategory("detection")]
    public float Detection() => _match.Motion.MeasureOverlap();

    /// <summary>The same through the frozen motion world.</summary>
    [Benchmark(Baseline = true)]
    [BenchmarkCategory("detection")]
    public float DetectionBaseline() => _baseline.Stepper.MeasureOverlap();

    /// <summary>Cycles 500 to 1,499 of the match, per cycle.</summary>
    [Benchmark(OperationsPerInvoke = MeasuredCycles)]
    [InvocationCount(1, 1)]
    [BenchmarkCategory("cycle")]
    public void Cycle()
    {
        for (int i = 0; i < MeasuredCycles; i++)
        {
            _match.Step();
        }
    }

    /// <summary>The same cycles of the same match with the frozen motion stage, per cycle.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = MeasuredCycles)]
    [InvocationCount(1, 1)]
    [BenchmarkCategory("cycle")]
    public void CycleBaseline()
    {
        for (int i = 0; i < MeasuredCycles; i++)
        {
            _baseline.Step();
        }
    }
}
