using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Server.Tests.Trace;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// The motion world finds its candidate pairs through a broad phase, at the start of each cycle and for
/// every body re-planned after a contact. Brute force (every pair of boxes) is the reference: the
/// grid, sweep and prune and the tree must give byte-identical traces over random scenarios, so
/// they found exactly the same pairs in the same order.
/// </summary>
public sealed class BroadPhaseChoiceTests
{
    public static TheoryData<int> Scenarios()
    {
        var data = new TheoryData<int>();
        for (int i = 0; i < 24; i += 3)
        {
            data.Add(i);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Scenarios))]
    public void EveryBroadPhaseGivesTheBruteForceTrace(int index)
    {
        var scenario = ScenarioFile.Parse(RandomScenarios.Json(index));
        byte[] truth = Trace(scenario, BroadPhaseKind.BruteForce);
        Assert.Equal(truth, Trace(scenario, BroadPhaseKind.UniformGrid));
        Assert.Equal(truth, Trace(scenario, BroadPhaseKind.SweepAndPrune));
        Assert.Equal(truth, Trace(scenario, BroadPhaseKind.DynamicAabbTree));
    }

    [Theory]
    [InlineData(150, 1UL)]
    [InlineData(400, 2UL)]
    public void ACrowdedSceneIsTheSameWithEveryBroadPhase(int movers, ulong seed)
    {
        var scenario = CrowdScenario.Create(movers, seed);
        byte[] truth = Trace(scenario, BroadPhaseKind.BruteForce, cycles: 30);
        Assert.Equal(truth, Trace(scenario, BroadPhaseKind.UniformGrid, cycles: 30));
        Assert.Equal(truth, Trace(scenario, BroadPhaseKind.SweepAndPrune, cycles: 30));
        Assert.Equal(truth, Trace(scenario, BroadPhaseKind.DynamicAabbTree, cycles: 30));
    }

    [Fact]
    public void TheDefaultMatchIsTheSameWithBruteForce()
    {
        var scenario = DefaultScenario.Load();
        Assert.Equal(Trace(scenario, BroadPhaseKind.BruteForce, cycles: 150), Trace(scenario, BroadPhaseKind.UniformGrid, cycles: 150));
    }

    private static byte[] Trace(ScenarioDefinition scenario, BroadPhaseKind broadPhase, int cycles = 60) =>
        TraceBytes.Of(MatchBuilder.Build(scenario, broadPhase: broadPhase), cycles);
}
