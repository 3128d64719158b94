namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// A strategy on its own thread reads a snapshot that its runner owns: a call given up on that
/// goes on reading sees the cycle it was asked about, not the match's snapshot and the referee's
/// variables as the next cycles rewrite them.
/// </summary>
public sealed class IsolatedSnapshotTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromMilliseconds(50);

    [Fact]
    public void AnAbandonedCallKeepsReadingTheValuesOfItsOwnCycle()
    {
        var variables = new MissionVariables();
        variables.Set("CompetitionPeriod", 0);
        variables.Set("Ball_0_Left_Status", 0);
        var snapshot = new MatchSnapshot(1, 0, [], 3000f, 2000f);
        snapshot.SetItem("抢球博弈", variables, 6000);
        snapshot.SetHeader(1, [0, 0]);
        snapshot.FishBuffer[0] = new FishView(0, 0, new Vector2(-100f, 50f), 0f, 0f, 0f, 160f, 30f, Decision.Stop);

        var clock = new ManualStrategyClock();
        var strategy = new ReadsAfterHanging(clock);
        var runner = new IsolatedStrategyRunner(strategy, 1, 0, clock);
        var decisions = new Decision[1];
        Assert.Equal(IsolatedStrategyRunner.Outcome.TimedOut, runner.Decide(snapshot, [0], decisions, Limit, Limit, out _, out _, out _));

        // The match moves on while the first call still runs: new cycle, fish moved, a ball scored.
        snapshot.SetHeader(2, [3, 0]);
        snapshot.FishBuffer[0] = snapshot.FishBuffer[0] with { Position = new Vector2(900f, -400f) };
        variables.Set("Ball_0_Left_Status", 1);
        clock.Release();

        // The second call waits for the first to return; then it sees cycle 2.
        Assert.Equal(IsolatedStrategyRunner.Outcome.Decided, runner.Decide(snapshot, [0], decisions, Limit, Limit, out var error, out _, out _));
        Assert.Null(error);
        runner.Stop();
        Assert.Equal(
            [(1, 0, "0", -100f), (2, 3, "1", 900f)],
            strategy.Seen);
        Assert.NotSame(snapshot, strategy.Snapshot);
        Assert.NotSame(variables, strategy.Snapshot!.Variables);
        Assert.Equal(["CompetitionPeriod", "Ball_0_Left_Status"], strategy.Snapshot.Variables.Keys);
    }

    private sealed class ReadsAfterHanging(ManualStrategyClock clock) : IStrategy
    {
        public System.Collections.Generic.List<(int Cycle, int Goals, string Status, float X)> Seen { get; } = [];

        public MatchSnapshot? Snapshot { get; private set; }

        public string TeamName => "reads after hanging";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            if (Seen.Count == 0)
            {
                clock.Hang(); // given up on; returns once the test releases it, after the source changed
            }

            Snapshot = snapshot;
            Seen.Add((snapshot.Cycle, snapshot.GoalsOf(0), snapshot.Variables["Ball_0_Left_Status"], snapshot.Fish[0].Position.X));
            decisions[0] = new Decision(5, 7);
        }
    }
}
