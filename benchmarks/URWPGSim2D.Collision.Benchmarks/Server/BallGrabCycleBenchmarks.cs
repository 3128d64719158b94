extern alias baseline;

using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;
using BaselineBuilder = baseline::URWPGSim2D.Server.Scenario.MatchBuilder;
using BaselineMatch = baseline::URWPGSim2D.Server.Simulation.Match;
using BaselineRegistry = baseline::URWPGSim2D.Server.Items.ItemRegistry;

namespace URWPGSim2D.Collision.Benchmarks.Server;

/// <summary>
/// The main job's whole cycle: the item 抢球博弈 ball-grab with its demo strategies on both teams
/// (as <c>run</c> plays it: four fish, nine balls, the item's layout, noise on), cycles 0 to 749 of
/// seeds 1 to 4, per cycle: the demos' planning, locomotion, motion with contacts, the referee.
/// Against the same item played by the whole server of the commit tagged <c>benchmark-baseline</c>
/// (<see cref="BaselineMatch"/>, its own demo strategies) in the same run. Each iteration builds
/// the four matches afresh, so every iteration measures the same cycles.
/// </summary>
[Config(typeof(BaselineConfig))]
public class BallGrabCycleBenchmarks
{
    private const string Item = "ball-grab";
    private const int Seeds = 4;
    private const int Cycles = 750;
    private readonly Match[] _matches = new Match[Seeds];
    private readonly BaselineMatch[] _baselines = new BaselineMatch[Seeds];

    /// <summary>Builds the item's match at seeds 1 to 4.</summary>
    [IterationSetup(Target = nameof(Cycle))]
    public void Setup()
    {
        var item = ItemRegistry.Find(Item)!;
        for (int i = 0; i < Seeds; i++)
        {
            ulong seed = (ulong)(i + 1);
            _matches[i] = MatchBuilder.Build(item.CreateScenario(seed), seed: seed);
        }
    }

    /// <summary>Builds the same matches on the frozen baseline.</summary>
    [IterationSetup(Target = nameof(CycleBaseline))]
    public void SetupBaseline()
    {
        var item = BaselineRegistry.Find(Item)!;
        for (int i = 0; i < Seeds; i++)
        {
            ulong seed = (ulong)(i + 1);
            _baselines[i] = BaselineBuilder.Build(item.CreateScenario(seed), seed: seed);
        }
    }

    /// <summary>Cycles 0 to 749 of ball-grab, demo against demo, at seeds 1 to 4, per cycle.</summary>
    [Benchmark(OperationsPerInvoke = Seeds * Cycles)]
    [InvocationCount(1, 1)]
    [BenchmarkCategory("ball-grab cycle, 4 seeds")]
    public void Cycle()
    {
        foreach (Match match in _matches)
        {
            for (int i = 0; i < Cycles && !match.IsOver; i++)
            {
                match.Step();
            }
        }
    }

    /// <summary>The same on the frozen baseline, per cycle.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Seeds * Cycles)]
    [InvocationCount(1, 1)]
    [BenchmarkCategory("ball-grab cycle, 4 seeds")]
    public void CycleBaseline()
    {
        foreach (BaselineMatch match in _baselines)
        {
            for (int i = 0; i < Cycles && !match.IsOver; i++)
            {
                match.Step();
            }
        }
    }
}
