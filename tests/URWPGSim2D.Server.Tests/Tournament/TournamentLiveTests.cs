using System.Globalization;
using System.Net;
using System.Net.Http;
using System.Text.RegularExpressions;
using URWPGSim2D.Server.Cli;
using URWPGSim2D.Server.Tests.Cli;
using URWPGSim2D.Server.Tests.Hosting;

namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// <c>tournament --live</c>, the projector view: the scheduled matches are played one after another
/// in the live page and recorded as a tournament off screen records them; on an address other
/// machines can reach the page only watches without the control token printed at start, and no
/// viewer can restart a tournament's match.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed partial class TournamentLiveTests() : TempFolderTest("urwpg-tour-live-")
{
    [Fact]
    public void The_matches_play_one_after_another_in_the_page_and_record_what_a_tournament_off_screen_records()
    {
        string[] tournament = ["tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "idle=idle", "--entrant", "chase=chase-ball", "--seeds", "1", "--cycles", "300"];
        int port = LiveRunTests.FreePort();
        string live = Path.Combine(Folder, "live"), off = Path.Combine(Folder, "off");
        var shown = CliRun.Of(string.Empty, [.. tournament, "--out", live, "--live", "--speed", "1000", "--port", port.ToString(CultureInfo.InvariantCulture)]);
        Assert.True(shown.ExitCode == 0, shown.Stderr);
        var played = CliRun.Of(string.Empty, [.. tournament, "--out", off]);
        Assert.True(played.ExitCode == 0, played.Stderr);

        Assert.Contains($"\nlive view: http://127.0.0.1:{port}/ (the matches play there one after another)\n", shown.Stdout, StringComparison.Ordinal);
        var lines = LiveLine().Matches(shown.Stdout).ToList();
        Assert.Equal(Enumerable.Range(0, 6), lines.Select(m => int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture))); // every match, in the schedule's order
        var results = File.ReadLines(Path.Combine(live, "results.jsonl")).Skip(1).ToList();
        Assert.Equal(File.ReadLines(Path.Combine(off, "results.jsonl")).Skip(1).Order(StringComparer.Ordinal), results.Order(StringComparer.Ordinal));
        Assert.Equal(File.ReadAllText(Path.Combine(off, "standings.json")), File.ReadAllText(Path.Combine(live, "standings.json")));
        for (int i = 0; i < lines.Count; i++)
        {
            Assert.Contains(string.Create(CultureInfo.InvariantCulture, $"\"goals\":[{lines[i].Groups[2].Value.Replace(':', ',')}]"), results[i], StringComparison.Ordinal);
        }
    }

    [Fact]
    public async Task On_every_interface_viewers_watch_only_the_control_link_pauses_and_nobody_restarts_a_match()
    {
        int port = LiveRunTests.FreePort();
        var output = new StringWriter();
        var console = new CliConsole(new StringReader(string.Empty), output, new StringWriter());
        using (var live = LiveTournament.Open("0.0.0.0", port, 1, console))
        {
            Assert.NotNull(live);
            string banner = output.ToString();
            Assert.StartsWith("live view: http://", banner, StringComparison.Ordinal);
            Assert.DoesNotContain("0.0.0.0", banner, StringComparison.Ordinal);
            var control = ControlLine().Match(banner);
            Assert.True(control.Success, banner);
            string token = control.Groups[1].Value;
            string home = $"http://127.0.0.1:{port}/";

            using var http = new HttpClient();
            var refused = await http.PostAsync(home + "control?action=pause", new StringContent(string.Empty));
            Assert.Equal(HttpStatusCode.Forbidden, refused.StatusCode);
            Assert.Equal("{\"control\":false}", await http.GetStringAsync(home + "access"));
            Assert.Equal(HttpStatusCode.NoContent, (await http.PostAsync(home + "control?action=pause&token=" + token, new StringContent(string.Empty))).StatusCode);
            var restart = await http.PostAsync(home + "control?action=restart&token=" + token, new StringContent(string.Empty));
            Assert.Equal(HttpStatusCode.BadRequest, restart.StatusCode);
            Assert.Equal("\"restart\": a tournament's matches are played once each, in turn (pause, resume or step)\n", await restart.Content.ReadAsStringAsync());
        }

        Assert.NotNull(LiveTournament.Open("127.0.0.1", port, 1, console) is { } again ? Dispose(again) : null); // the port is free again
    }

    [Theory]
    [InlineData("--port 8090", "--port, --host and --speed belong to --live")]
    [InlineData("--live --check", "--live plays the matches on this machine, one after another, in the page: it does not go with --check, --slurm, --shard, --merge or --replays")]
    [InlineData("--live --replays", "--live plays the matches on this machine, one after another, in the page: it does not go with --check, --slurm, --shard, --merge or --replays")]
    [InlineData("--live --speed 0", "--speed must be a number 0.01..1000 (times real time), got \"0\"")]
    public void Bad_live_options_are_one_line_and_exit_2(string options, string message)
    {
        var run = CliRun.Of(string.Empty, ["tournament", "--item", "ball-grab", "--entrant", "a=demo", "--entrant", "b=idle", "--out", Path.Combine(Folder, "t"), .. options.Split(' ')]);
        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith("tournament: " + message + ". Usage: ", run.Stderr, StringComparison.Ordinal);
        Assert.Empty(Directory.GetFileSystemEntries(Folder));
    }

    private static object Dispose(IDisposable d)
    {
        d.Dispose();
        return d;
    }

    [GeneratedRegex(@"live: match ([0-9]+) \(seed 1\) over: ([0-9]+:[0-9]+)\n")]
    private static partial Regex LiveLine();

    [GeneratedRegex(@"\ncontrol: http://127\.0\.0\.1:[0-9]+/\?token=([0-9a-f]{32}) \(this link alone can pause, resume and step the matches: keep it to yourself; the addresses above only watch\)\n")]
    private static partial Regex ControlLine();
}
