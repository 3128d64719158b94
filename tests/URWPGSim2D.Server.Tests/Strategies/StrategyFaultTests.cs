using URWPGSim2D.Server.Cli;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Strategies;
using URWPGSim2D.Server.Tests.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Strategies;

/// <summary>A strategy that throws or runs too long does not stop the match; its fish keep their last decisions.</summary>
public sealed class StrategyFaultTests
{
    private const string TwoFish = """{"fish":[{"team":0,"position":[-500,0]},{"team":1,"position":[500,0],"heading":3.14159}],"balls":[]}""";

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void AThrowingStrategyLeavesItsFishOnTheirLastDecision(bool isolated)
    {
        var teams = new TeamStrategy?[] { new("throwing", new ThrowingStrategy(), isolated), null };
        var match = TestMatches.FromJson(TwoFish, teams);
        match.Play(20);

        var slot = match.Strategies.Slots[0];
        Assert.Equal(15, slot.Exceptions);
        Assert.Equal(0, slot.Timeouts);
        Assert.Equal(new Decision(15, 7), match.World.Fish[0].Decision);
        Assert.Equal(317f * (1f - System.MathF.Pow(0.9f, 20)), match.World.Fish[0].Speed.Value, 1e-2f); // VCode 15 for all 20 cycles: 317·(1 − 0.9^20)
        Assert.Equal(20, match.Statistics.Cycles);
        string summary = MatchSummary.Format(match, System.TimeSpan.FromMilliseconds(1));
        Assert.Contains("team 0 (throwing): 15 exceptions, 0 timeouts; its fish kept their last decisions; first: cycle 6: InvalidOperationException: strategy bug", summary, System.StringComparison.Ordinal);
    }

    [Fact]
    public void ATooSlowStrategyIsSkippedAndItsLateAnswerDiscarded()
    {
        var teams = new TeamStrategy?[] { new("slow", new SlowStrategy(), Isolated: true), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50);
        for (int k = 0; k < 8; k++)
        {
            match.Step();
            Assert.Equal(new Decision(9, 9), match.World.Fish[0].Decision);
        }

        var slot = match.Strategies.Slots[0];
        Assert.True(slot.Timeouts >= 1, "the slow cycle timed out");
        Assert.Equal(0, slot.Exceptions);
        Assert.StartsWith("cycle 4: no decision within 50 ms", slot.FirstFault, System.StringComparison.Ordinal);
    }

    [Fact]
    public void BuiltInStrategiesDecideAsNamed()
    {
        var match = TestMatches.FromJson("""
            {"fish":[{"team":0,"position":[-500,-300],"strategy":"idle"},
                     {"team":0,"position":[-500,300],"decision":{"vcode":12,"tcode":3}},
                     {"team":1,"position":[500,0],"heading":3.14159,"strategy":"chase-ball"}],
             "balls":[{"position":[0,0]}]}
            """);
        match.Step();
        Assert.Equal(Decision.Stop, match.World.Fish[0].Decision);
        Assert.Equal(new Decision(12, 3), match.World.Fish[1].Decision);
        Assert.True(match.World.Fish[2].Decision.VCode > 0, "chase-ball swims toward the ball");
    }

    [Fact]
    public void DecisionsAreClamped()
    {
        Assert.Equal((15, 0), (new Decision(40, -3).VCode, new Decision(40, -3).TCode));
    }
}
