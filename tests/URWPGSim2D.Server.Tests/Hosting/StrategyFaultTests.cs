using URWPGSim2D.Server.Cli;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Hosting;
using URWPGSim2D.Server.Tests.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>A strategy that throws or runs too long does not stop the match; its fish keep their last decisions.</summary>
public sealed class StrategyFaultTests
{
    private const string TwoFish = """{"fish":[{"team":0,"position":[-500,0]},{"team":1,"position":[500,0],"heading":3.14159}],"balls":[]}""";

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void AThrowingStrategyLeavesItsFishOnTheirLastDecision(bool isolated)
    {
        var teams = new TeamStrategy?[] { new("throwing", new ThrowingStrategy(), isolated, new ManualStrategyClock()), null };
        var match = TestMatches.FromJson(TwoFish, teams);
        match.Play(20);

        var slot = match.Strategies.Slots[0];
        Assert.Equal(15, slot.Exceptions);
        Assert.Equal(0, slot.Timeouts);
        Assert.Equal(new Decision(15, 7), match.World.Fish[0].Decision);
        Assert.Equal(317f * (1f - System.MathF.Pow(0.9f, 20)), match.World.Fish[0].Speed.Value, 1e-2f); // VCode 15 for all 20 cycles: 317·(1 − 0.9^20)
        Assert.Equal(20, match.Statistics.Cycles);
        string summary = MatchSummary.Format(match, System.TimeSpan.FromMilliseconds(1));
        Assert.Contains("team 0 (throwing): 15 exceptions, 0 timeouts, 0 bad answers; its fish kept their last decisions; first: cycle 6: InvalidOperationException: strategy bug", summary, System.StringComparison.Ordinal);
    }

    [Fact]
    public void ATooSlowStrategyIsSkippedAndItsLateAnswerDiscarded()
    {
        var clock = new ManualStrategyClock();
        var teams = new TeamStrategy?[] { new("slow", new SlowStrategy(clock), Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50);
        for (int k = 0; k < 8; k++)
        {
            match.Step();
            Assert.Equal(new Decision(9, 9), match.World.Fish[0].Decision);
        }

        match.Strategies.Stop();
        var slot = match.Strategies.Slots[0];
        Assert.Equal(1, slot.Timeouts);
        Assert.Equal(0, slot.Exceptions);
        Assert.StartsWith("cycle 4: no decision within 50 ms", slot.FirstFault, System.StringComparison.Ordinal);
    }

    [Fact]
    public void AStrategyJustWithinItsDeadlineIsAccepted()
    {
        var clock = new ManualStrategyClock();
        var teams = new TeamStrategy?[] { new("slow", new SlowStrategy(clock) { Spend = System.TimeSpan.FromMilliseconds(50) }, Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50);
        match.Play(5);
        match.Strategies.Stop();
        Assert.Equal(0, match.Strategies.Slots[0].Timeouts);
        Assert.Equal(new Decision(9, 9), match.World.Fish[0].Decision);
        Assert.Equal(new Decision(1, 1), Cycle3Answer(clock));
    }

    [Fact]
    public void AStrategyThatHangsIsSkippedWhileBusyAndTheMatchGoesOn()
    {
        var clock = new ManualStrategyClock();
        var teams = new TeamStrategy?[] { new("hang", new HangingStrategy(clock), Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50);
        match.Play(10);
        clock.Release();
        match.Strategies.Stop();
        var slot = match.Strategies.Slots[0];
        Assert.Equal(10, match.World.Cycle);
        Assert.Equal(8, slot.Timeouts); // cycle 3 hangs, cycles 4..10 find it still busy
        Assert.Equal(new Decision(9, 9), match.World.Fish[0].Decision);
        Assert.Equal("cycle 3: no decision within 50 ms", slot.FirstFault);
    }

    // What SlowStrategy answers at cycle 3 when its time is within the deadline: it is accepted.
    private static Decision Cycle3Answer(ManualStrategyClock clock)
    {
        var teams = new TeamStrategy?[] { new("slow", new SlowStrategy(clock) { Spend = System.TimeSpan.FromMilliseconds(50) }, Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50);
        match.Play(4);
        match.Strategies.Stop();
        return match.World.Fish[0].Decision;
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
