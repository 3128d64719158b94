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

        var slot = match.Caller().Slots[0];
        Assert.Equal(15, slot.Exceptions);
        Assert.Equal(0, slot.Timeouts);
        Assert.Equal(new Decision(15, 7), match.World.Fish[0].Decision);
        Assert.Equal(317f * (1f - System.MathF.Pow(0.9f, 20)), match.World.Fish[0].Speed.Value, 1e-2f); // VCode 15 for all 20 cycles: 317·(1 − 0.9^20)
        Assert.Equal(20, match.Statistics.Cycles);
        string summary = MatchSummary.Format(match, System.TimeSpan.FromMilliseconds(1));
        Assert.Contains("team 0 (throwing): 15 exceptions, 0 timeouts, 0 bad answers; its fish kept their last decisions; first: cycle 6: InvalidOperationException: strategy bug", summary, System.StringComparison.Ordinal);
    }

    [Fact]
    public void ALateCallIsWaitedForItsAnswerCountsAndItsOverrunIsPaidFromTheBank()
    {
        // Cycle 4's call uses 400 ms against a deadline of 50 ms (100 ms of wall time): 350 ms from the bank.
        var clock = new ManualStrategyClock();
        var teams = new TeamStrategy?[] { new("slow", new SlowStrategy(clock), Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50, timeBank: System.TimeSpan.FromSeconds(1));
        var seen = new Decision[8];
        for (int k = 0; k < 8; k++)
        {
            match.Step();
            seen[k] = match.World.Fish[0].Decision;
        }

        match.Teams.Stop();
        var slot = match.Caller().Slots[0];
        Assert.Equal([new(9, 9), new(9, 9), new(9, 9), new(1, 1), new(9, 9), new(9, 9), new(9, 9), new(9, 9)], seen);
        Assert.Equal(0, slot.Faults);
        Assert.Equal(1, slot.Bank!.LateCalls);
        Assert.Equal(System.TimeSpan.FromMilliseconds(350), slot.Bank.Used);
        Assert.Equal(System.TimeSpan.FromMilliseconds(400), slot.Bank.Slowest);
        string summary = MatchSummary.Format(match, System.TimeSpan.FromMilliseconds(1));
        Assert.Contains("strategy faults: none\nstrategy time: 50 ms of CPU time a call, a time bank of 1.0 s a team for late calls:\n  team 0 (slow): 1 late call, 0.350 s drawn, slowest call 400 ms\n", summary, System.StringComparison.Ordinal);
    }

    [Fact]
    public void ACallBeyondWhatTheBankHoldsSpendsItAndTheTeamPlaysIdle()
    {
        var clock = new ManualStrategyClock();
        var slow = new SlowStrategy(clock);
        var teams = new TeamStrategy?[] { new("slow", slow, Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50, timeBank: System.TimeSpan.FromMilliseconds(200));
        var seen = new Decision[8];
        for (int k = 0; k < 8; k++)
        {
            match.Step();
            seen[k] = match.World.Fish[0].Decision;
        }

        match.Teams.Stop();
        var slot = match.Caller().Slots[0];
        Assert.Equal([new(9, 9), new(9, 9), new(9, 9), Decision.Stop, Decision.Stop, Decision.Stop, Decision.Stop, Decision.Stop], seen);
        Assert.Equal(4, slow.Calls); // not asked again after its bank was spent
        Assert.Equal(1, slot.Timeouts);
        Assert.Equal(4, slot.IdleFromCycle);
        Assert.True(slot.Bank!.Spent);
        // The call is given up on as soon as it has used its 50 ms and the 200 ms bank: its answer never counts.
        Assert.Equal("cycle 4: time bank spent: no decision within 0.25 s of CPU time or 0.7 s; the team plays idle for the rest of the match", slot.FirstFault);
        string summary = MatchSummary.Format(match, System.TimeSpan.FromMilliseconds(1));
        Assert.Contains("team 0 (slow): 0 exceptions, 1 timeouts, 0 bad answers, out of time in cycle 4; its fish kept their last decisions until then and stopped after", summary, System.StringComparison.Ordinal);
        Assert.Contains("  team 0 (slow): 1 late call, 0.200 s drawn, bank spent, slowest call 700 ms\n", summary, System.StringComparison.Ordinal);
    }

    [Fact]
    public void AStrategyJustWithinItsDeadlineIsAccepted()
    {
        var clock = new ManualStrategyClock();
        var teams = new TeamStrategy?[] { new("slow", new SlowStrategy(clock) { Spend = System.TimeSpan.FromMilliseconds(50) }, Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50);
        match.Play(5);
        match.Teams.Stop();
        Assert.Equal(0, match.Caller().Slots[0].Timeouts);
        Assert.Equal(0, match.Caller().Slots[0].Bank!.LateCalls);
        Assert.Equal(new Decision(9, 9), match.World.Fish[0].Decision);
        Assert.Equal(new Decision(1, 1), Cycle3Answer(clock));
    }

    [Fact]
    public void AStrategyThatHangsIsGivenUpOnWhenItsBankIsSpentAndTheMatchGoesOn()
    {
        var clock = new ManualStrategyClock();
        var teams = new TeamStrategy?[] { new("hang", new HangingStrategy(clock), Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50, timeBank: System.TimeSpan.FromSeconds(2));
        match.Play(10);
        clock.Release();
        match.Teams.Stop();
        var slot = match.Caller().Slots[0];
        Assert.Equal(10, match.World.Cycle);
        Assert.Equal(1, slot.Timeouts); // given up on once; idle after
        Assert.Equal(3, slot.IdleFromCycle);
        Assert.Equal(Decision.Stop, match.World.Fish[0].Decision);
        Assert.Equal("cycle 3: time bank spent: no decision within 2.05 s of CPU time or 6.1 s; the team plays idle for the rest of the match", slot.FirstFault);
    }

    // What SlowStrategy answers at cycle 3 when its time is within the deadline: it is accepted.
    private static Decision Cycle3Answer(ManualStrategyClock clock)
    {
        var teams = new TeamStrategy?[] { new("slow", new SlowStrategy(clock) { Spend = System.TimeSpan.FromMilliseconds(50) }, Isolated: true, clock), null };
        var match = TestMatches.FromJson(TwoFish, teams, timeoutMs: 50);
        match.Play(4);
        match.Teams.Stop();
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
