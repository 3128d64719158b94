using BenchmarkDotNet.Attributes;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Collision.Benchmarks.Scaling;

/// <summary>
/// One whole cycle of a crowd scene (<see cref="CrowdScenario"/>: fish and balls at the default
/// match's density, the pool growing with the count, fish on fixed random decisions) for 100,
/// 1,000 and 10,000 fish and balls, with the stepper's broad phase a uniform grid or brute force
/// (every pair of boxes tested). Both give the same match (tested); only the cost differs. The
/// scene is played 20 cycles before measuring (the starting overlaps are resolved in the first
/// ones); each call plays the next cycle.
/// </summary>
[MemoryDiagnoser]
public class ScalingBenchmarks
{
    private Match _grid = null!;
    private Match _brute = null!;

    /// <summary>Fish and balls in the scene.</summary>
    [Params(100, 1_000, 10_000)]
    public int Objects { get; set; }

    /// <summary>Builds the scene twice (grid and brute force) and plays 20 cycles of each.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var scene = CrowdScenario.Create(Objects);
        _grid = MatchBuilder.Build(scene, broadPhase: BroadPhaseKind.UniformGrid);
        _brute = MatchBuilder.Build(scene, broadPhase: BroadPhaseKind.BruteForce);
        for (int i = 0; i < 20; i++)
        {
            _grid.Step();
            _brute.Step();
        }
    }

    /// <summary>One cycle, uniform grid broad phase.</summary>
    [Benchmark(Baseline = true)]
    public void Grid() => _grid.Step();

    /// <summary>One cycle, brute-force broad phase.</summary>
    [Benchmark]
    public void BruteForce() => _brute.Step();
}
