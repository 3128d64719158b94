using URWPGSim2D.Engine.Items.FourTeams;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// 4支队伍测试 against the original's <c>Match4Teams</c> (its layout; it has no rules), and a match of
/// four teams through the server: the summary, the trace, the strategies per team, the results and
/// the batch aggregate and merge. One test plays teams in strategy hosts and remotely beside parallel
/// tests: a late answer is waited for and paid from the team's time bank, so the results do not
/// depend on how busy the machine is.
/// </summary>
public sealed class FourTeamsTests() : TempFolderTest("urwpg-four-")
{
    private static readonly FourTeamsItem Item = new();

    [Fact]
    public void TheLayoutIsTheOriginals()
    {
        var s = Item.CreateScenario(1);
        Assert.Equal((3000f, 2000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Empty(s.Obstacles);
        var ball = Assert.Single(s.Balls);
        Assert.Equal((Vector2.Zero, 58f), (ball.Position, ball.Radius));

        // Three body lengths (160) from each wall; the others three body widths (45) either side.
        (int Team, Vector2 Position, float Heading)[] original =
        [
            (0, new(-1020, 0), 0f), (0, new(-1020, 135), 0f), (0, new(-1020, -135), 0f),
            (1, new(1020, 0), MathF.PI), (1, new(1020, 135), MathF.PI), (1, new(1020, -135), MathF.PI),
            (2, new(0, -520), MathF.PI / 2f), (2, new(135, -520), MathF.PI / 2f), (2, new(-135, -520), MathF.PI / 2f),
            (3, new(0, 520), -MathF.PI / 2f), (3, new(135, 520), -MathF.PI / 2f), (3, new(-135, 520), -MathF.PI / 2f),
        ];
        Assert.Equal(original, s.Fish.Select(f => (f.Team, f.Position, f.Heading)).ToArray());
        Assert.Equal(("4支队伍测试", 4, 3), (Item.ChineseName, Item.TeamCount, Item.FishPerTeam));
    }

    [Fact]
    public void ItHasNoRulesTheTimeEndsIt()
    {
        var match = ItemTestMatches.Build(Item, 50, "demo", 1, noise: true);
        Assert.Equal(50, match.PlayAll());
        Assert.Equal(new[] { 0, 0, 0, 0 }, match.Referee!.Scores);
        Assert.Equal(new URWPGSim2D.Engine.Items.MatchOutcome(-1, "no rules: a test of four teams"), match.Referee.Outcome);
        Assert.Equal(new[] { "end" }, match.Referee.Events.Select(e => e.Kind).ToArray());
        Assert.Equal(4, match.TeamCount);
    }

    [Fact]
    public void RunPlaysFourTeamsEachWithItsOwnStrategy()
    {
        string trace = Path.Combine(Folder, "t.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--item", "four-teams", "--cycles", "20", "--strategy", "2=idle", "--strategy", "3=chase-ball", "--trace", trace);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("score: team 0 (four-teams demo) 0, team 1 (four-teams demo) 0, team 2 (idle) 0, team 3 (chase-ball) 0\n", run.Stdout, StringComparison.Ordinal);
        string[] lines = File.ReadAllLines(trace);
        using var first = JsonDocument.Parse(lines[0]);
        var teams = first.RootElement.GetProperty("layout").GetProperty("teams");
        Assert.Equal(new[] { "four-teams demo", "four-teams demo", "idle", "chase-ball" }, teams.EnumerateArray().Select(t => t.GetProperty("name").GetString()).ToArray());
        Assert.All(lines, l => Assert.Equal("[0,0,0,0]", JsonDocument.Parse(l).RootElement.GetProperty("score").GetRawText()));

        // Team 2 idles: its fish have not moved.
        using var last = JsonDocument.Parse(lines[^1]);
        for (int i = 6; i < 9; i++)
        {
            Assert.Equal(first.RootElement.GetProperty("fish")[i].GetProperty("position").GetRawText(), last.RootElement.GetProperty("fish")[i].GetProperty("position").GetRawText());
        }
    }

    [Fact]
    public void TeamsTwoAndThreePlayInAStrategyHostAndRemotelyTheSameMatchAsInProcess()
    {
        string steady = URWPGSim2D.Server.Tests.Hosting.SteadyStrategy.Write(Folder);
        string local = Path.Combine(Folder, "local.jsonl"), hosted = Path.Combine(Folder, "hosted.jsonl"), remote = Path.Combine(Folder, "remote.jsonl");
        string[] match = ["run", "--item", "four-teams", "--cycles", "40", "--seed", "5", "--strategy-timeout", "20000", "--strategy", "2=" + steady];
        var a = CliRun.Of(string.Empty, [.. match, "--strategy", "3=chase-ball", "--isolation", "none", "--trace", local]);
        var b = CliRun.Of(string.Empty, [.. match, "--strategy", "3=chase-ball", "--trace", hosted]);
        var (c, client) = URWPGSim2D.Server.Tests.Hosting.Remote.RemoteMatchTests.Remote(
            [.. match, "--strategy", "3=remote:0", "--trace", remote], port => ["connect", $"127.0.0.1:{port}", "chase-ball"]);
        Assert.True(a.ExitCode == 0 && b.ExitCode == 0 && c.ExitCode == 0 && client.ExitCode == 0, a.Stderr + b.Stderr + c.Stderr + client.Stderr);
        Assert.Contains("strategy faults: none", b.Stdout, StringComparison.Ordinal);
        Assert.Contains("strategy faults: none", c.Stdout, StringComparison.Ordinal);
        Assert.Equal("match ended after 40 cycles: 0:0:0:0, 0 fault(s) charged to this team\n", client.Stdout);

        // Cycle by cycle the same (the header's team names differ: remote:PORT); team 3 chased the ball.
        string[] x = File.ReadAllLines(local), y = File.ReadAllLines(hosted), z = File.ReadAllLines(remote);
        Assert.Equal(x, y);
        Assert.Equal(x[1..], z[1..]);
        using var first = JsonDocument.Parse(x[0]);
        using var last = JsonDocument.Parse(x[^1]);
        Assert.NotEqual(first.RootElement.GetProperty("fish")[9].GetProperty("position").GetRawText(), last.RootElement.GetProperty("fish")[9].GetProperty("position").GetRawText());
    }

    [Fact]
    public void BatchResultsAndMergeKeepFourTeams()
    {
        string all = Path.Combine(Folder, "all.jsonl"), s0 = Path.Combine(Folder, "s0.jsonl"), s1 = Path.Combine(Folder, "s1.jsonl"), merged = Path.Combine(Folder, "m.jsonl");
        var whole = CliRun.Of(string.Empty, "run", "--item", "four-teams", "--batch", "2", "--cycles", "10", "--results", all);
        Assert.True(whole.ExitCode == 0, whole.Stderr);
        Assert.Contains("goals team 3 (four-teams demo): mean 0.000", whole.Stdout, StringComparison.Ordinal);
        Assert.Contains("outcomes: team 0 won 0, team 1 won 0, team 2 won 0, team 3 won 0, drawn 2\n", whole.Stdout, StringComparison.Ordinal);
        using (var match = JsonDocument.Parse(File.ReadLines(all).Skip(1).First()))
        {
            Assert.Equal("[0,0,0,0]", match.RootElement.GetProperty("score").GetRawText());
        }

        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--item", "four-teams", "--batch", "2", "--cycles", "10", "--shard", "0/2", "--results", s0).ExitCode);
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--item", "four-teams", "--batch", "2", "--cycles", "10", "--shard", "1/2", "--results", s1).ExitCode);
        var merge = CliRun.Of(string.Empty, "merge", "--out", merged, s0, s1);
        Assert.True(merge.ExitCode == 0, merge.Stderr);
        Assert.Contains("outcomes: team 0 won 0, team 1 won 0, team 2 won 0, team 3 won 0, drawn 2\n", merge.Stdout, StringComparison.Ordinal);
        Assert.Equal(File.ReadAllBytes(all), File.ReadAllBytes(merged));
    }

    [Fact]
    public void AStrategyForATeamTheSceneLacksIsRefused()
    {
        var run = CliRun.Of(string.Empty, "run", "--item", "transport", "--strategy", "3=idle");
        Assert.Equal(2, run.ExitCode);
        Assert.Equal("run: --strategy 3: the scene has no team 3 (teams 0 to 1)\n", run.Stderr);
    }
}
