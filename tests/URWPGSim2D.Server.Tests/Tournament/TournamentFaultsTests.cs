using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// A tournament shows its entrants' runtime faults — exceptions, timeouts, bad answers, host ends —
/// in the terminal, standings.json, standings.md and report.html, with the first fault's match and
/// cycle, linked to that cycle of the match's replay page when the page was written.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class TournamentFaultsTests() : TempFolderTest("urwpg-tour-faults-")
{
    private string Thrower() => SdkStrategy.Write(Folder, "Thrower", "thrower", """
        if (s.Cycle == 20 || s.Cycle == 40) throw new InvalidOperationException("boom at " + s.Cycle);
        for (int i = 0; i < d.Length; i++) d[i] = new Decision(8, 7);
        """);

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Every_view_shows_each_entrants_faults_and_where_the_first_one_is(bool replays)
    {
        string tour = Path.Combine(Folder, replays ? "with" : "without");
        string[] args = ["tournament", "--item", "ball-grab", "--entrant", "thrower=" + Thrower(), "--entrant", "idle=idle", "--seeds", "1", "--cycles", "60",
            "--strategy-timeout", "5000", "--isolation", "none", "--out", tour, .. replays ? (string[])["--replays"] : []];
        var run = CliRun.Of(string.Empty, args);
        Assert.True(run.ExitCode == 0, run.Stderr);

        // The results keep the first fault as "cycle N: message"; match 0 is the first with one.
        var first = File.ReadLines(Path.Combine(tour, "results.jsonl")).Skip(1).Select(l => JsonDocument.Parse(l).RootElement)
            .Where(l => l.TryGetProperty("faults", out _)).OrderBy(l => l.GetProperty("index").GetInt32()).First();
        int match = first.GetProperty("index").GetInt32();
        string firstText = first.GetProperty("faults")[0].GetProperty("first").GetString()!;
        var m = Regex.Match(firstText, @"^cycle (\d+): (InvalidOperationException: boom at 20)$");
        Assert.True(m.Success, firstText);
        int cycle = int.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
        string link = $"replays/match-{match}.html#cycle={cycle}";
        string where = $"match {match}, cycle {cycle}";

        // The terminal: one line per entrant with faults (both matches, two exceptions each).
        string line = $"  thrower: 4 exceptions in 2 matches; first: {where}: InvalidOperationException: boom at 20" + (replays ? $" ({Path.Combine(tour, link)})" : string.Empty) + "\n";
        Assert.Contains("runtime faults (exceptions, timeouts, bad answers, host ends):\n" + line, run.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("  idle:", run.Stdout, StringComparison.Ordinal);

        // standings.json: "faults" on the entrant that had them only.
        using var json = JsonDocument.Parse(File.ReadAllText(Path.Combine(tour, "standings.json")));
        var entrants = json.RootElement.GetProperty("entrants").EnumerateArray().ToDictionary(e => e.GetProperty("name").GetString()!);
        Assert.False(entrants["idle"].TryGetProperty("faults", out _));
        var faults = entrants["thrower"].GetProperty("faults");
        Assert.Equal(4, faults.GetProperty("exceptions").GetInt32());
        Assert.Equal(0, faults.GetProperty("timeouts").GetInt32());
        Assert.Equal(0, faults.GetProperty("badAnswers").GetInt32());
        Assert.Equal(0, faults.GetProperty("hostEnds").GetInt32());
        Assert.Equal(2, faults.GetProperty("matches").GetInt32());
        var firstJson = faults.GetProperty("first");
        Assert.Equal(match, firstJson.GetProperty("match").GetInt32());
        Assert.Equal(cycle, firstJson.GetProperty("cycle").GetInt32());
        Assert.Equal("InvalidOperationException: boom at 20", firstJson.GetProperty("text").GetString());
        Assert.Equal(replays, firstJson.TryGetProperty("replay", out var replay));
        if (replays)
        {
            Assert.Equal(link, replay.GetString());
            Assert.True(File.Exists(Path.Combine(tour, "replays", $"match-{match}.html")));
        }

        // standings.md: a table of the faults.
        string md = File.ReadAllText(Path.Combine(tour, "standings.md"));
        Assert.Contains("| Entrant | Exceptions | Timeouts | Bad answers | Host ends | Matches | First fault |\n", md, StringComparison.Ordinal);
        Assert.Contains($"| thrower | 4 | 0 | 0 | 0 | 2 | {(replays ? $"[{where}]({link})" : where)}: InvalidOperationException: boom at 20 |\n", md, StringComparison.Ordinal);

        // report.html: the same, the first fault linked to its cycle.
        string html = File.ReadAllText(Path.Combine(tour, "report.html"));
        Assert.Contains("<h2>Runtime faults</h2>", html, StringComparison.Ordinal);
        Assert.Contains(replays ? $"<a href=\"{link}\">{where}</a>: InvalidOperationException: boom at 20" : $"<td class=\"l err\">{where}: InvalidOperationException: boom at 20", html, StringComparison.Ordinal);
    }

    [Fact]
    public void A_tournament_without_faults_shows_no_faults_section()
    {
        string tour = Path.Combine(Folder, "clean");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "a=idle", "--entrant", "b=chase-ball", "--seeds", "1", "--cycles", "20", "--out", tour);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.DoesNotContain("runtime faults", run.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("\"faults\"", File.ReadAllText(Path.Combine(tour, "standings.json")), StringComparison.Ordinal);
        Assert.DoesNotContain("Runtime faults", File.ReadAllText(Path.Combine(tour, "standings.md")), StringComparison.Ordinal);
        Assert.DoesNotContain("Runtime faults", File.ReadAllText(Path.Combine(tour, "report.html")), StringComparison.Ordinal);
    }
}
