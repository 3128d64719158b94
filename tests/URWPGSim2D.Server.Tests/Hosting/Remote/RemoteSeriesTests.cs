using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Hosting.Remote;

/// <summary>
/// A remote client that plays a series (<c>"series":true</c>, what <c>connect</c> says): a tournament's
/// remote entrant (<c>--entrant NAME=remote:PORT</c>) connects once and plays every one of its matches
/// on that connection, named in the standings by the name its client sent; <c>run --live</c> plays a
/// remote team (the remote options of <c>tournament</c> are checked with <c>run</c>'s, in
/// <see cref="RemoteMatchTests"/>). Server and client each run on a thread of the test over loopback TCP.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class RemoteSeriesTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-series-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void A_remote_entrant_connects_once_and_plays_each_of_its_matches_in_turn()
    {
        string outDir = Path.Combine(_folder, "t");
        string[] tournament = ["tournament", "--item", "polo-1v1", "--entrant", "alice=remote:0", "--entrant", "bob=chase-ball", "--entrant", "carol=idle",
            "--entrant", "dave=remote:0", "--seeds", "1", "--cycles", "30", "--strategy-timeout", "20000", "--out", outDir];
        var stderr = new WatchedWriter();
        var server = RemoteMatchTests.Background(tournament, stderr);
        int[] ports = stderr.WaitForPorts(2); // both entrants' ports, before any client has connected
        Assert.NotEqual(ports[0], ports[1]);
        Assert.DoesNotContain("connected from", stderr.ToString(), StringComparison.Ordinal);
        Assert.Matches(@"^entrant alice \(remote\): waiting for a client on 127\.0\.0\.1:\d+\nentrant dave \(remote\): waiting for a client on 127\.0\.0\.1:\d+\n", stderr.ToString());

        CliRun? second = null;
        var other = new Thread(() => second = CliRun.Of(string.Empty, "connect", $"127.0.0.1:{ports[1]}", "idle")) { IsBackground = true };
        other.Start();
        var first = CliRun.Of(string.Empty, "connect", $"127.0.0.1:{ports[0]}", "chase-ball");
        other.Join();
        var result = server();
        Assert.True(result.ExitCode == 0 && first.ExitCode == 0 && second!.ExitCode == 0, result.Stdout + result.Stderr + first.Stderr + second!.Stderr);

        // Every match was played (no forfeit), each remote entrant's on its one connection: one line per match on its client.
        var (_, records, _) = TournamentFile.Read(Path.Combine(outDir, TournamentOutputs.Results));
        Assert.NotEmpty(records);
        Assert.All(records, r => Assert.False(r.IsForfeit, string.Join("; ", r.Reasons)));
        int Matches(string name) => records.Count(r => r.Entrants.Contains(name));
        Assert.True(Matches("alice") >= 3, "alice plays every other entrant");
        Assert.Equal(Matches("alice"), Lines(first.Stdout));
        Assert.Equal(Matches("dave"), Lines(second.Stdout));
        Assert.Single(Regex.Matches(result.Stderr, @"entrant alice \(remote\): client ""chase-ball"" connected from"));
        Assert.Single(Regex.Matches(result.Stderr, @"entrant dave \(remote\): client ""idle"" connected from"));

        // The standings know each remote entrant by its name and show the name its client sent.
        string standings = File.ReadAllText(Path.Combine(outDir, TournamentOutputs.StandingsMarkdownName));
        Assert.Contains("\n| alice | remote:0 | - | chase-ball |\n", standings, StringComparison.Ordinal);
        Assert.Contains("\n| dave | remote:0 | - | idle |\n", standings, StringComparison.Ordinal);
    }

    [Fact]
    public void A_remote_entrant_whose_client_does_not_come_forfeits_its_matches_and_the_others_play()
    {
        string outDir = Path.Combine(_folder, "t");
        var result = CliRun.Of(string.Empty, "tournament", "--item", "polo-1v1", "--entrant", "ghost=remote:0", "--entrant", "bob=chase-ball", "--entrant", "carol=idle",
            "--seeds", "1", "--cycles", "10", "--remote-wait", "1", "--out", outDir);
        Assert.True(result.ExitCode == 0, result.Stdout + result.Stderr);
        var (_, records, _) = TournamentFile.Read(Path.Combine(outDir, TournamentOutputs.Results));
        Assert.Equal(6, records.Count);
        foreach (var r in records)
        {
            Assert.False(r.Failed); // not a failure of the server: a re-run plays it again
            bool ghost = r.Entrants.Contains("ghost");
            Assert.Equal(ghost, r.IsForfeit);
            if (ghost)
            {
                Assert.Equal([r.Entrants.ToList().IndexOf("ghost")], r.Forfeits);
                Assert.Matches(@"^--entrant ghost=remote: no client connected to 127\.0\.0\.1:\d+ within 1 s \(--remote-wait\)$", r.Reasons[0]);
            }
        }
    }

    [Fact]
    public async Task A_live_match_plays_a_remote_team_named_by_its_client()
    {
        var options = RunOptions.Parse(["--live", "--speed", "100", "--cycles", "20", "--item", "polo-1v1", "--seed", "1", "--strategy", "0=remote:0", "--strategy", "1=idle",
            "--strategy-timeout", "20000", "--port", LiveRunTests.FreePort().ToString(CultureInfo.InvariantCulture)]);
        var output = new LiveRunTests.SignallingWriter("match over");
        var stderr = new WatchedWriter();
        var console = new CliConsole(new StringReader(string.Empty), output, stderr);
        var teams = RunCommand.LoadTeams(options, console);
        using var stop = new CancellationTokenSource();
        var served = Task.Run(() => LiveRun.Serve(options, ItemRegistry.Find("polo-1v1")!.CreateScenario(1), teams, console, stop.Token, _ => { }));
        int port = stderr.WaitForPort();
        CliRun? client = null;
        var connect = new Thread(() => client = CliRun.Of(string.Empty, "connect", $"127.0.0.1:{port}", "chase-ball")) { IsBackground = true };
        connect.Start();

        Assert.True(await Task.WhenAny(output.Seen, served, Task.Delay(120_000)) == output.Seen, "no summary: " + output + " / stderr: " + stderr);
        Assert.Matches(@"\nscore: team 0 \(chase-ball \[remote:\d+\]\) \d+, team 1 \(idle\) \d+\n", "\n" + output);
        stop.Cancel();
        Assert.Equal(0, await served);
        teams[0]!.Remote!.Dispose(); // the run ends: the client, kept for a restart, reads the end of the stream
        connect.Join();
        Assert.True(client!.ExitCode == 0, client.Stderr);
        Assert.Matches(@"^match ended after \d+ cycles: \d+:\d+, 0 fault\(s\) charged to this team\n$", client.Stdout); // one match: a tie plays on past the 20 cycles
    }

    private static int Lines(string text) => Regex.Matches(text, @"^match ended after \d+ cycles: \d+:\d+, \d+ fault\(s\) charged to this team$", RegexOptions.Multiline).Count;
}
