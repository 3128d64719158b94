using URWPGSim2D.Server.Tests.Trace;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// Invariants over many random scenarios (fish with every strategy, fast balls of three sizes,
/// thin and round obstacles, both pool sizes, with and without goal blocks and noise): after every
/// cycle nothing is outside the pool and no pair overlaps by more than 1 mm, checked by brute force;
/// and the same scenario and seed give byte-identical traces.
/// </summary>
public sealed class InvariantTests
{
    private const int Scenarios = 24;
    private const int Cycles = 120;

    public static TheoryData<int> Indices()
    {
        var data = new TheoryData<int>();
        for (int i = 0; i < Scenarios; i++)
        {
            data.Add(i);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Indices))]
    public void NothingEscapesAndNothingOverlapsAfterAnyCycle(int index)
    {
        string json = RandomScenarios.Json(index);
        var match = MatchBuilder.Build(ScenarioFile.Parse(json));
        for (int k = 1; k <= Cycles; k++)
        {
            match.Step();
            float deepest = OverlapAudit.DeepestOverlap(match.World, out string where);
            Assert.True(deepest <= 1f, $"scenario {index}, cycle {k}: {where} overlaps {deepest} mm\n{json}");
            Assert.True(match.Motion.LeftoverOverlap <= 1f);
        }
    }

    [Theory]
    [InlineData(2UL, 400)]
    [InlineData(7UL, 400)]
    [InlineData(12UL, 1130)] // a ball squeezed between fish at cycle 1125 (7.8 mm left without the relaxation passes)
    public void TheDefaultMatchKeepsItsJamsApart(ulong seed, int cycles)
    {
        // Chase-ball makes every fish fight for the same balls: balls squeezed between fish, fish
        // against goal blocks. The motion world's own measure every cycle, the audit every 25th.
        var match = MatchBuilder.Build(DefaultScenario.Load(), seed: seed);
        for (int k = 1; k <= cycles; k++)
        {
            match.Step();
            Assert.True(match.Motion.LeftoverOverlap <= 1f, $"seed {seed}, cycle {k}: {match.Motion.LeftoverOverlap} mm left");
            if (k % 25 == 0)
            {
                float deepest = OverlapAudit.DeepestOverlap(match.World, out string where);
                Assert.True(deepest <= 1f, $"seed {seed}, cycle {k}: {where} overlaps {deepest} mm");
            }
        }
    }

    [Theory]
    [InlineData(300, 1UL)]
    [InlineData(300, 2UL)]
    public void ACrowdedSceneKeepsEverythingApart(int movers, ulong seed)
    {
        var match = MatchBuilder.Build(CrowdScenario.Create(movers, seed));
        for (int k = 1; k <= 60; k++)
        {
            match.Step();
            Assert.True(match.Motion.LeftoverOverlap <= 1f, $"cycle {k}: {match.Motion.LeftoverOverlap} mm left");
            if (k % 15 == 0)
            {
                float deepest = OverlapAudit.DeepestOverlap(match.World, out string where);
                Assert.True(deepest <= 1f, $"cycle {k}: {where} overlaps {deepest} mm");
            }
        }
    }

    [Fact]
    public void TheAuditSeesOverlapsAndEscapesAndTheScenariosCoverEveryKind()
    {
        var overlapping = TestMatches.Balls(string.Empty, 0f, 0f, 0f, 0f, 100f, 0f, 0f, 0f);
        Assert.Equal(16f, OverlapAudit.DeepestOverlap(overlapping.World, out _), 1e-3f);
        overlapping.World.Balls[0].Position = new System.Numerics.Vector2(1480f, 0f);
        Assert.Equal(38f, OverlapAudit.DeepestOverlap(overlapping.World, out string where), 1e-3f);
        Assert.Equal("ball0 outside", where);

        int fish = 0, balls = 0, obstacles = 0;
        for (int i = 0; i < Scenarios; i++)
        {
            var s = ScenarioFile.Parse(RandomScenarios.Json(i));
            fish += s.Fish.Count;
            balls += s.Balls.Count;
            obstacles += s.Obstacles.Count;
        }

        Assert.True(fish >= 30 && balls >= 60 && obstacles >= 20, $"{fish} fish, {balls} balls, {obstacles} obstacles");
    }

    [Theory]
    [InlineData(3)]
    [InlineData(8)]
    [InlineData(15)]
    public void TheSameScenarioAndSeedGiveByteIdenticalTraces(int index)
    {
        var scenario = ScenarioFile.Parse(RandomScenarios.Json(index));
        byte[] first = Trace(scenario, seed: 5);
        byte[] second = Trace(scenario, seed: 5);
        Assert.Equal(first, second);
        Assert.Equal(81, CountLines(first));
    }

    [Fact]
    public void TheDefaultMatchTraceDependsOnTheSeedWhenNoiseIsOn()
    {
        var scenario = DefaultScenario.Load();
        Assert.NotEqual(Trace(scenario, seed: 1), Trace(scenario, seed: 2));
        Assert.Equal(Trace(scenario, seed: 1), Trace(scenario, seed: 1));
    }

    private static byte[] Trace(ScenarioDefinition scenario, ulong seed) => TraceBytes.Of(MatchBuilder.Build(scenario, seed: seed), 80);

    private static int CountLines(byte[] bytes) => Array.FindAll(bytes, b => b == (byte)'\n').Length;
}
