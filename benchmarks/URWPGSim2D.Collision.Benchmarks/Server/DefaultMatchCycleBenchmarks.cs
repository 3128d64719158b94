using BenchmarkDotNet.Attributes;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Collision.Benchmarks.Server;

/// <summary>
/// One cycle of the embedded default match (4 fish, 9 balls, 4 obstacles, 4 goal blocks, walls),
/// 500 cycles into the match so that fish and balls are in play. <see cref="Detection"/> is the
/// detection alone: broad phase and every candidate pair's exact test at the current state (no
/// motion, no response). <see cref="Cycle"/> is the whole 100 ms cycle: strategies, locomotion,
/// sub-stepped motion with times of first contact and responses, rules. Each call of
/// <see cref="Cycle"/> plays the next cycle of the same match.
/// </summary>
[MemoryDiagnoser]
public class DefaultMatchCycleBenchmarks
{
    private Match _match = null!;

    /// <summary>Builds the default match and plays its first 500 cycles.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _match = MatchBuilder.Build(DefaultScenario.Load());
        for (int i = 0; i < 500; i++)
        {
            _match.Step();
        }
    }

    /// <summary>Broad phase plus the exact test of every candidate pair; returns the deepest overlap.</summary>
    [Benchmark]
    public float Detection() => _match.Stepper.MeasureOverlap();

    /// <summary>One whole cycle of the match.</summary>
    [Benchmark]
    public void Cycle() => _match.Step();
}
