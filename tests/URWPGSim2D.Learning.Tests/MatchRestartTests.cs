using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Teams;
using URWPGSim2D.Engine.Trace;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Learning.Tests;

/// <summary>
/// A match restarted in place after playing other decisions plays, cycle by cycle, the trace line a
/// match built anew with the same seed plays; a batch's episodes then allocate nothing across their ends.
/// </summary>
public sealed class MatchRestartTests
{
    [Fact]
    public void ARestartedMatchsFirstFishBallContactIsAFirstContactAgain()
    {
        // Played to its first fish-ball contact (cycle k) and restarted with the same seed and
        // decisions, the match meets the ball at cycle k again: a first contact of the cycle (the
        // exchange), as in a new match, not a repeat of the old match's contact of its cycle k.
        var item = ItemRegistry.Find("polo-1v1")!;
        var (played, playedPushed) = Build(item, "idle", 5, noise: false);
        int k = 0;
        while (!played.Contacts.Cycle.ToArray().Any(c => c.Pair.Kind == URWPGSim2D.Engine.Simulation.PairKind.FishBall) && k < 200)
        {
            Push(playedPushed, ++k, 0);
            played.Step();
        }

        Assert.True(k < 200, "no fish-ball contact in 200 cycles");
        played.Restart(5);
        var (fresh, freshPushed) = Build(item, "idle", 5, noise: false);
        var playedLine = new TraceLine(played.World, played.Teams, played.Rules);
        var freshLine = new TraceLine(fresh.World, fresh.Teams, fresh.Rules);
        for (int cycle = 1; cycle <= k + 20; cycle++)
        {
            Push(playedPushed, cycle, 0);
            Push(freshPushed, cycle, 0);
            played.Step();
            fresh.Step();
            Assert.Equal(freshLine.Write(fresh.Contacts.Cycle).ToArray(), playedLine.Write(played.Contacts.Cycle).ToArray());
        }
    }

    [Fact]
    public void ARestartForgetsTheTouchesTheMatchLeft()
    {
        var item = ItemRegistry.Find("polo-1v1")!;
        var (played, pushed) = Build(item, "chase-ball", 103, noise: true);
        int cycle = 0;
        while (played.World.Motion.TouchingPairs == 0 && cycle < 160)
        {
            Push(pushed, ++cycle, 7);
            played.Step();
        }

        Assert.True(played.World.Motion.TouchingPairs > 0, $"nothing touched in {cycle} cycles");
        played.Restart(3);
        Assert.Equal(0, played.World.Motion.TouchingPairs);
    }

    [Theory]
    [InlineData("polo-1v1", "chase-ball", true)]
    [InlineData("polo-1v1", "idle", false)]
    [InlineData("polo-3v3", "demo", true)]
    [InlineData("polo-5v5", "chase-ball", true)]
    [InlineData("polo-5v5", "demo", false)]
    public void ARestartedMatchPlaysWhatAMatchBuiltAnewPlays(string slug, string opponent, bool noise)
    {
        var item = ItemRegistry.Find(slug)!;
        foreach (ulong seed in new ulong[] { 3, 11 })
        {
            // Played first with other decisions and another seed, for long enough to score, foul and change ends (160 cycles of 200).
            var (played, playedPushed) = Build(item, opponent, seed + 100, noise);
            for (int cycle = 1; cycle <= 160; cycle++)
            {
                Push(playedPushed, cycle, 7);
                played.Step();
            }

            Assert.True(played.World.Cycle == 160 && played.Rules.Events.Count > 0, $"{slug}: the first match recorded no event");
            // Touches the old match left would hold pairs a new match does not hold: the restart forgets them.
            played.Restart(seed);
            Assert.Equal(0, played.World.Motion.TouchingPairs);
            var (fresh, freshPushed) = Build(item, opponent, seed, noise);
            var playedLine = new TraceLine(played.World, played.Teams, played.Rules);
            var freshLine = new TraceLine(fresh.World, fresh.Teams, fresh.Rules);
            Assert.Equal(fresh.Seed, played.Seed);
            for (int cycle = 1; cycle <= 300; cycle++)
            {
                Assert.Equal(freshLine.Write(fresh.Contacts.Cycle).ToArray(), playedLine.Write(played.Contacts.Cycle).ToArray());
                Push(playedPushed, cycle, 0);
                Push(freshPushed, cycle, 0);
                played.Step();
                fresh.Step();
            }

            Assert.Equal(freshLine.Write(fresh.Contacts.Cycle).ToArray(), playedLine.Write(played.Contacts.Cycle).ToArray());
            Assert.Equal(fresh.Rules.Events.ToArray(), played.Rules.Events.ToArray());
            Assert.Equal(fresh.Rules.Scores, played.Rules.Scores);
            Assert.Equal(fresh.Contacts.ByKind.ToArray(), played.Contacts.ByKind.ToArray());
            Assert.Equal(
                (fresh.Statistics.Cycles, fresh.Statistics.SubSteps, fresh.Statistics.MostSubSteps, fresh.Statistics.Events, fresh.Statistics.LargestLeftoverOverlap, fresh.Statistics.LargestLeftoverCycle),
                (played.Statistics.Cycles, played.Statistics.SubSteps, played.Statistics.MostSubSteps, played.Statistics.Events, played.Statistics.LargestLeftoverOverlap, played.Statistics.LargestLeftoverCycle));
            Assert.Equal(fresh.Rules.Variables.ToArray(), played.Rules.Variables.ToArray());
        }
    }

    [Fact]
    public void OnlyAMatchWhoseItemAndStrategiesRestartCanRestart()
    {
        var ballGrab = ItemRegistry.Find("ball-grab")!;
        Assert.False(MatchSetup.Create(ballGrab.CreateScenario(1), [new IdleStrategy(), new IdleStrategy()]).CanRestart);
        var polo = ItemRegistry.Find("polo-1v1")!;
        Assert.True(MatchSetup.Create(polo.CreateScenario(1), [new IdleStrategy(), new ChaseBallStrategy()]).CanRestart);
        var foreign = MatchSetup.Create(polo.CreateScenario(1), [new Foreign(), new IdleStrategy()]);
        Assert.False(foreign.CanRestart);
        Assert.Throws<InvalidOperationException>(() => foreign.Restart(2));
    }

    [Fact]
    public void APoloBatchAllocatesNothingAcrossEpisodeEnds()
    {
        // Episodes of 40 cycles (half time at 20): 130 steps after warm-up cross three episode ends in every match.
        foreach (string opponent in MatchBatch.Opponents)
        {
            var run = new PatternRun(new MatchBatch("polo-1v1", opponent, 8, 0, 40));
            var ends = new int[run.Batch.Count];
            long total = 0;
            for (int step = 0; step < 170; step++)
            {
                long allocated = run.Step(step);
                if (step >= 40)
                {
                    // After the first episode (the code's first runs, the buffers' sizing).
                    total += allocated;
                    for (int i = 0; i < ends.Length; i++)
                    {
                        ends[i] += run.Terminated[i] || run.Truncated[i] ? 1 : 0;
                    }
                }
            }

            Assert.All(ends, n => Assert.True(n >= 3, $"{n} episode ends against {opponent}"));
            Assert.Equal(0, total);
        }
    }

    private static (Match Match, PushedDecisions Pushed) Build(URWPGSim2D.Engine.Items.CompetitionItem item, string opponent, ulong seed, bool noise)
    {
        var scenario = item.CreateScenario(seed);
        var pushed = new PushedDecisions(scenario.Fish.Count(f => f.Team == 0));
        IStrategy? other = opponent switch { "idle" => new IdleStrategy(), "chase-ball" => new ChaseBallStrategy(), _ => null };
        var match = MatchSetup.Create(scenario, [pushed, other], seed: seed, noise: noise, cycles: 200);
        return (match, pushed);
    }

    private static void Push(PushedDecisions pushed, int cycle, int salt)
    {
        var pending = pushed.Pending;
        for (int k = 0; k < pending.Length; k++)
        {
            pending[k] = new Decision(((cycle * 5) + k + salt) % 16, ((cycle * 3) + (2 * k) + salt) % 16);
        }
    }

    private sealed class Foreign : IStrategy
    {
        public string TeamName => "foreign";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions) => decisions.Fill(Decision.Stop);
    }
}
