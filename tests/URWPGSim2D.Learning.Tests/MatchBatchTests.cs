using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Trace;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Learning.Tests;

/// <summary>
/// A batch's match is the engine's match of the same item, seed and decisions (the match <c>run</c>
/// plays: the engine's MatchSetup equals the server line for line), its observation is what the
/// strategies see, it follows the next-step autoreset convention, allocates nothing per step, and
/// refuses bad arguments by name.
/// </summary>
public sealed class MatchBatchTests
{
    [Theory]
    [InlineData("polo-1v1", "chase-ball", 0)]
    [InlineData("polo-1v1", "idle", 1)]
    [InlineData("polo-3v3", "demo", 0)]
    public void EachMatchIsTheEnginesMatchOfTheSameSeedAndDecisions(string slug, string opponent, int team)
    {
        ulong[] seeds = [3, 4, 9];
        const int cycles = 120;
        var batch = new MatchBatch(slug, opponent, seeds.Length, team, cycles);
        var obs = new float[batch.Count * batch.ObservationSize];
        var actions = new int[batch.Count * batch.ActionSize];
        var rewards = new float[batch.Count];
        var terminated = new bool[batch.Count];
        var truncated = new bool[batch.Count];
        batch.Reset(seeds, obs);
        var item = ItemRegistry.Find(slug)!;
        var references = new Match[seeds.Length];
        var scripted = new Scripted[seeds.Length];
        var lines = new (TraceLine Batch, TraceLine Reference)[seeds.Length];
        for (int i = 0; i < seeds.Length; i++)
        {
            scripted[i] = new Scripted(i);
            var teams = new IStrategy?[2];
            teams[team] = scripted[i];
            teams[1 - team] = opponent switch { "idle" => new IdleStrategy(), "chase-ball" => new ChaseBallStrategy(), _ => null };
            references[i] = MatchSetup.Create(item.CreateScenario(seeds[i]), teams, seed: seeds[i], cycles: cycles);
            var mine = batch.MatchAt(i);
            mine.Rules.EventTexts = true; // the trace lines carry the events' texts the batch leaves out
            lines[i] = (new TraceLine(mine.World, mine.Teams, mine.Rules), new TraceLine(references[i].World, references[i].Teams, references[i].Rules));
        }

        for (int step = 0; step < cycles; step++)
        {
            for (int i = 0; i < seeds.Length; i++)
            {
                Assert.Equal(lines[i].Reference.Write(references[i].Contacts.Cycle).ToArray(), lines[i].Batch.Write(batch.MatchAt(i).Contacts.Cycle).ToArray());
                for (int k = 0; k < batch.ActionSize / 2; k++)
                {
                    var d = Scripted.At(i, step + 1, k);
                    actions[(i * batch.ActionSize) + (2 * k)] = d.VCode;
                    actions[(i * batch.ActionSize) + (2 * k) + 1] = d.TCode;
                }
            }

            for (int i = 0; i < seeds.Length; i++)
            {
                references[i].Step();
                // The batch's observation before this step is what the strategy saw deciding it.
                Assert.Equal(ObservationOf(scripted[i].Seen!, cycles), obs.AsSpan(i * batch.ObservationSize, batch.ObservationSize).ToArray());
                scripted[i].Seen = null;
            }

            batch.Step(actions, obs, rewards, terminated, truncated);
            for (int i = 0; i < seeds.Length; i++)
            {
                Assert.False(terminated[i] && truncated[i]);
                Assert.Equal(step + 1 == cycles, terminated[i] || truncated[i]);
            }
        }

        for (int i = 0; i < seeds.Length; i++)
        {
            Assert.Equal(references[i].Rules.Scores, batch.MatchAt(i).Rules.Scores);
        }
    }

    [Fact]
    public void RewardsAreTheChangeOfTheScoreDifferenceAndSumToIt()
    {
        // The batch's team plays the item's demo (decided from the batch's own snapshot) against chase-ball: goals fall.
        var batch = new MatchBatch("polo-1v1", "chase-ball", 4, 0, 1200);
        var obs = new float[batch.Count * batch.ObservationSize];
        var rewards = new float[batch.Count];
        var terminated = new bool[batch.Count];
        var truncated = new bool[batch.Count];
        var actions = new int[batch.Count * batch.ActionSize];
        batch.Reset([1, 2, 3, 4], obs);
        var item = ItemRegistry.Find("polo-1v1")!;
        var drivers = new IStrategy[batch.Count];
        var sums = new float[batch.Count];
        var done = new bool[batch.Count];
        var decisions = new Decision[1];
        for (int i = 0; i < batch.Count; i++)
        {
            drivers[i] = item.CreateDemoStrategy(0, batch.MatchAt(i).Referee!);
        }

        for (int step = 0; step < 1200 && Array.IndexOf(done, false) >= 0; step++)
        {
            for (int i = 0; i < batch.Count; i++)
            {
                if (!done[i])
                {
                    drivers[i].Decide(batch.MatchAt(i).Observe(), [0], decisions);
                    actions[2 * i] = decisions[0].VCode;
                    actions[(2 * i) + 1] = decisions[0].TCode;
                }
            }

            batch.Step(actions, obs, rewards, terminated, truncated);
            for (int i = 0; i < batch.Count; i++)
            {
                if (!done[i])
                {
                    sums[i] += rewards[i];
                    done[i] = terminated[i] || truncated[i];
                    var scores = batch.MatchAt(i).Rules.Scores;
                    Assert.Equal(scores[0] - scores[1], sums[i]);
                }
            }
        }

        Assert.Contains(sums, s => s != 0);
    }

    [Fact]
    public void AnEpisodeCutAtItsCyclesIsTruncatedAndTheNextStepStartsTheNextSeed()
    {
        // Polo after a 0:0 normal time plays on (extra time): the episode is cut, truncated.
        var batch = new MatchBatch("polo-1v1", "idle", 2, 0, 30);
        var obs = new float[batch.Count * batch.ObservationSize];
        var rewards = new float[2];
        var terminated = new bool[2];
        var truncated = new bool[2];
        var actions = new int[2 * batch.ActionSize];
        Array.Fill(actions, 7);
        batch.Reset([5, 6], obs, maxSteps: 0);
        for (int step = 1; step <= 30; step++)
        {
            batch.Step(actions, obs, rewards, terminated, truncated);
            Assert.Equal([step == 30, step == 30], truncated);
            Assert.Equal([false, false], terminated);
        }

        Assert.Equal(1f, obs[batch.ObservationSize - 1]);
        batch.Step(actions, obs, rewards, terminated, truncated);
        Assert.Equal([0f, 0f], rewards);
        Assert.Equal([false, false], truncated);
        var cycles = new int[2];
        var goals = new int[4];
        var seeds = new ulong[2];
        batch.Info(cycles, goals, seeds);
        Assert.Equal([0, 0], cycles);
        Assert.Equal([MatchBatch.NextSeed(5), MatchBatch.NextSeed(6)], seeds);
        var fresh = new MatchBatch("polo-1v1", "idle", 2, 0, 30);
        var first = new float[obs.Length];
        fresh.Reset(seeds, first);
        Assert.Equal(first, obs);
    }

    [Fact]
    public void AMatchItsItemEndsIsTerminatedAndMaxStepsTruncatesEarlier()
    {
        var batch = new MatchBatch("ball-grab", "chase-ball", 1, 0, 40);
        var obs = new float[batch.ObservationSize];
        var rewards = new float[1];
        var terminated = new bool[1];
        var truncated = new bool[1];
        var actions = new int[batch.ActionSize];
        batch.Reset([2], obs);
        int steps = 0;
        do
        {
            batch.Step(actions, obs, rewards, terminated, truncated);
            steps++;
        }
        while (!terminated[0] && !truncated[0]);
        Assert.Equal(40, steps);
        Assert.True(terminated[0]);
        Assert.False(truncated[0]);

        batch.Reset([2], obs, maxSteps: 7);
        steps = 0;
        do
        {
            batch.Step(actions, obs, rewards, terminated, truncated);
            steps++;
        }
        while (!terminated[0] && !truncated[0]);
        Assert.Equal(7, steps);
        Assert.True(truncated[0]);
    }

    [Fact]
    public void AStepWithinAnEpisodeAllocatesNothingEvenWhenTheRefereeRecordsEvents()
    {
        // Half time falls at cycle 200 of 400: every match records an event (and goals, fouls, dead balls as they come).
        foreach (string opponent in MatchBatch.Opponents)
        {
            var run = new PatternRun(new MatchBatch("polo-1v1", opponent, 16, 0, 400));
            var batch = run.Batch;
            long total = 0;
            for (int step = 0; step < 390; step++)
            {
                long allocated = run.Step(step);
                if (step >= 20)
                {
                    // After the first steps (the code's first runs, the strategies' own buffers, the motion world's sizing).
                    total += allocated;
                }

                Assert.DoesNotContain(true, run.Terminated);
                Assert.DoesNotContain(true, run.Truncated);
            }

            int events = 0;
            for (int i = 0; i < batch.Count; i++)
            {
                var recorded = batch.MatchAt(i).Rules.Events;
                events += recorded.Count;
                Assert.Contains(recorded, e => e.Kind == "half-time" && e.Cycle == 200);
                Assert.All(recorded, e => Assert.Equal(string.Empty, e.Text));
            }

            Assert.Equal(0, total);
            Assert.True(events >= batch.Count, $"{events} events against {opponent}");
        }
    }

    [Theory]
    [InlineData("polo-1v1", "chase-ball")]
    [InlineData("polo-3v3", "demo")]
    [InlineData("ball-grab", "chase-ball")]
    public void TheBatchsEventsAreTheEnginesWithoutTheirTexts(string slug, string opponent)
    {
        // The engine's match of the same seed and decisions records the same events, texts and all.
        const int cycles = 600;
        var batch = new MatchBatch(slug, opponent, 1, 0, cycles);
        var obs = new float[batch.ObservationSize];
        var actions = new int[batch.ActionSize];
        batch.Reset([7], obs);
        var item = ItemRegistry.Find(slug)!;
        var reference = MatchSetup.Create(
            item.CreateScenario(7),
            [new Scripted(0), opponent switch { "idle" => new IdleStrategy(), "chase-ball" => new ChaseBallStrategy(), _ => null }],
            seed: 7,
            cycles: cycles);
        var mine = batch.MatchAt(0);
        for (int step = 0; step < cycles && !reference.IsOver; step++)
        {
            for (int k = 0; k < batch.ActionSize / 2; k++)
            {
                var d = Scripted.At(0, step + 1, k);
                actions[2 * k] = d.VCode;
                actions[(2 * k) + 1] = d.TCode;
            }

            reference.Step();
            batch.Step(actions, obs, new float[1], new bool[1], new bool[1]);
        }

        var expected = reference.Rules.Events;
        Assert.NotEmpty(expected);
        Assert.All(expected, e => Assert.NotEqual(string.Empty, e.Text));
        Assert.Equal(expected.Select(e => e with { Text = string.Empty }).ToArray(), mine.Rules.Events.ToArray());
    }

    [Fact]
    public void BadArgumentsAreRefusedByName()
    {
        Assert.StartsWith("item: unknown item \"polo-2v2\" (one of ", Refused("item", () => new MatchBatch("polo-2v2")), StringComparison.Ordinal);
        Assert.StartsWith("opponent: unknown opponent \"chase\" (one of idle, chase-ball, demo)", Refused("opponent", () => new MatchBatch("polo-1v1", "chase")), StringComparison.Ordinal);
        Assert.StartsWith("count: 0 matches", Refused("count", () => new MatchBatch("polo-1v1", "idle", 0)), StringComparison.Ordinal);
        Assert.StartsWith("team: 2, expected 0 to 1 in polo-1v1", Refused("team", () => new MatchBatch("polo-1v1", "idle", 1, 2)), StringComparison.Ordinal);
        Assert.StartsWith("cycles: 0, expected 1 or more", Refused("cycles", () => new MatchBatch("polo-1v1", "idle", 1, 0, 0)), StringComparison.Ordinal);
        var batch = new MatchBatch("polo-1v1", "idle", 2);
        var obs = new float[2 * batch.ObservationSize];
        var one = new float[2];
        var flags = new bool[2];
        Assert.Throws<InvalidOperationException>(() => batch.Step(new int[4], obs, one, flags, new bool[2]));
        Assert.StartsWith("seeds: length 1, expected 2", Refused("seeds", () => batch.Reset([1], obs)), StringComparison.Ordinal);
        Assert.StartsWith("observations: length 3, expected", Refused("observations", () => batch.Reset([1, 2], new float[3])), StringComparison.Ordinal);
        Assert.StartsWith("maxSteps: -1", Refused("maxSteps", () => batch.Reset([1, 2], obs, -1)), StringComparison.Ordinal);
        batch.Reset([1, 2], obs);
        Assert.StartsWith("actions: length 3, expected 4", Refused("actions", () => batch.Step(new int[3], obs, one, flags, new bool[2])), StringComparison.Ordinal);
        Assert.StartsWith("actions[1][0]: 16, expected an integer 0..15 (speed code of fish 0", Refused("actions", () => batch.Step([0, 7, 16, 7], obs, one, flags, new bool[2])), StringComparison.Ordinal);
        Assert.StartsWith("actions[0][1]: -1", Refused("actions", () => batch.Step([0, -1, 0, 7], obs, one, flags, new bool[2])), StringComparison.Ordinal);
        Assert.StartsWith("truncated: length 1, expected 2", Refused("truncated", () => batch.Step([0, 7, 0, 7], obs, one, flags, new bool[1])), StringComparison.Ordinal);
        Assert.Equal(0, batch.MatchAt(0).World.Cycle); // nothing was played by a refused step
    }

    private static string Refused(string name, Action act)
    {
        var e = Assert.ThrowsAny<ArgumentException>(act);
        Assert.Equal(name, e.ParamName);
        return e.Message;
    }

    private static float[] ObservationOf(MatchSnapshot s, int cycles)
    {
        var values = new List<float>();
        foreach (var f in s.Fish)
        {
            values.AddRange([(float)(f.Position.X / 1000.0), (float)(f.Position.Y / 1000.0), (float)Math.Cos(f.Heading), (float)Math.Sin(f.Heading), (float)(f.Speed / 1000.0)]);
        }

        foreach (var b in s.Balls)
        {
            values.AddRange([(float)(b.Position.X / 1000.0), (float)(b.Position.Y / 1000.0), (float)(b.Velocity.X / 1000.0), (float)(b.Velocity.Y / 1000.0)]);
        }

        values.Add((float)Math.Min((double)s.Cycle / cycles, 1.0));
        return [.. values];
    }

    // Decides from the match's number and the cycle alone, as the test pushes; keeps what it saw.
    private sealed class Scripted(int match) : IStrategy
    {
        public MatchSnapshot? Seen { get; set; }

        public string TeamName => "pushed";

        public static Decision At(int match, int cycle, int k) => new(((cycle * 5) + k + match) % 16, ((cycle * 3) + (2 * k) + match) % 16);

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            Seen = snapshot; // refilled at the next cycle only
            for (int k = 0; k < fish.Length; k++)
            {
                decisions[k] = At(match, snapshot.Cycle + 1, k);
            }
        }
    }
}
