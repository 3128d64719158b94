using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// <c>tournament --entrants-dir DIR</c>: every sub-folder, .cs file and DLL of DIR is an entrant
/// named after it, versioned by a hash of its files; a re-run plays again only the matches of an
/// entrant whose code changed, and a late entrant's matches, keeping the rest (and their replay
/// pages); the standings and the report list each entrant's code, version and own team name.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class TournamentEntrantsDirTests() : TempFolderTest("urwpg-tour-dir-")
{
    private static string Sdk(string type, string team, int speed) =>
        SdkStrategy.Source(type, team, $"for (int i = 0; i < d.Length; i++) d[i] = new Decision({speed}, 7);");

    private CliRun Tournament(string dir, string tour, params string[] more)
    {
        URWPGSim2D.Hosting.CompiledImages.Forget();
        return CliRun.Of(string.Empty, ["tournament", "--item", "ball-grab", "--entrants-dir", dir, "--seeds", "1", "--cycles", "10", "--isolation", "none",
            "--strategy-timeout", "5000", "--replays", "--out", tour, .. more]);
    }

    [Fact]
    public void A_folder_of_entrants_replays_only_what_changed_and_adds_a_late_entrant()
    {
        string dir = Path.Combine(Folder, "class");
        Directory.CreateDirectory(Path.Combine(dir, "alpha"));
        File.WriteAllText(Path.Combine(dir, "alpha", "Alpha.cs"), Sdk("Alpha", "Team Alpha", 5));
        File.WriteAllText(Path.Combine(dir, "beta.cs"), Sdk("Beta", "Team Beta", 6));
        File.WriteAllText(Path.Combine(dir, "gamma.cs"), Sdk("Gamma", "Team Gamma", 7));
        File.WriteAllText(Path.Combine(dir, "notes.txt"), "not an entrant");
        string tour = Path.Combine(Folder, "tour");

        var first = Tournament(dir, tour);
        Assert.True(first.ExitCode == 0, first.Stderr);
        Assert.StartsWith("tournament: ball-grab, 3 entrants, 1 seed, 6 matches; 6 to play, 0 already there\n", first.Stdout, StringComparison.Ordinal);
        string md = File.ReadAllText(Path.Combine(tour, "standings.md"));
        Assert.Matches(@"\| alpha \| " + Regex.Escape(Path.Combine(dir, "alpha")) + @" \| [0-9a-f]{12} \| Team Alpha \|\n", md);
        Assert.Matches(@"\| beta \| " + Regex.Escape(Path.Combine(dir, "beta.cs")) + @" \| [0-9a-f]{12} \| Team Beta \|\n", md);
        Assert.Contains("<td class=\"l\">Team Gamma</td>", File.ReadAllText(Path.Combine(tour, "report.html")), StringComparison.Ordinal);

        var again = Tournament(dir, tour);
        Assert.True(again.ExitCode == 0, again.Stderr);
        Assert.StartsWith("tournament: ball-grab, 3 entrants, 1 seed, 6 matches; 0 to play, 6 already there\n", again.Stdout, StringComparison.Ordinal);

        // beta's code changes: its 4 matches are played again, alpha against gamma (both sides) stays.
        string before = VersionOf(tour, "beta");
        File.WriteAllText(Path.Combine(dir, "beta.cs"), Sdk("Beta", "Team Beta 2", 9));
        var changed = Tournament(dir, tour);
        Assert.True(changed.ExitCode == 0, changed.Stderr);
        Assert.StartsWith("tournament: ball-grab, 3 entrants, 1 seed, 6 matches; 4 to play, 2 already there, 4 matches of changed or removed entrants dropped\n", changed.Stdout, StringComparison.Ordinal);
        Assert.NotEqual(before, VersionOf(tour, "beta"));
        Assert.Contains("| Team Beta 2 |", File.ReadAllText(Path.Combine(tour, "standings.md")), StringComparison.Ordinal);

        // A late entrant: only its 6 matches are played; the 6 others keep their results and replay pages.
        var late = Tournament(dir, tour, "--entrant", "late=idle");
        Assert.True(late.ExitCode == 0, late.Stderr);
        Assert.StartsWith("tournament: ball-grab, 4 entrants, 1 seed, 12 matches; 6 to play, 6 already there\n", late.Stdout, StringComparison.Ordinal);
        Assert.Equal(13, File.ReadAllLines(Path.Combine(tour, "results.jsonl")).Length);
        Assert.Equal(12, Directory.GetFiles(Path.Combine(tour, "replays"), "match-*.html").Length);
        var fresh = Tournament(dir, Path.Combine(Folder, "fresh"), "--entrant", "late=idle");
        Assert.True(fresh.ExitCode == 0, fresh.Stderr);
        Assert.Equal(File.ReadAllText(Path.Combine(Path.Combine(Folder, "fresh"), "standings.json")), File.ReadAllText(Path.Combine(tour, "standings.json")));
        Assert.Equal(File.ReadAllLines(Path.Combine(Path.Combine(Folder, "fresh"), "results.jsonl")).Skip(1), File.ReadAllLines(Path.Combine(tour, "results.jsonl")).Skip(1));
    }

    [Fact]
    public void A_folder_that_gives_no_entrant_or_a_name_twice_is_one_line_and_exit_2()
    {
        string empty = Path.Combine(Folder, "empty");
        Directory.CreateDirectory(empty);
        var none = Tournament(empty, Path.Combine(Folder, "t1"));
        Assert.Equal(2, none.ExitCode);
        Assert.StartsWith($"tournament: --entrants-dir \"{empty}\" holds no sub-folder, .cs file or .dll file. Usage: ", none.Stderr, StringComparison.Ordinal);

        string twice = Path.Combine(Folder, "twice");
        Directory.CreateDirectory(Path.Combine(twice, "a"));
        File.WriteAllText(Path.Combine(twice, "a.cs"), Sdk("A", "a", 5));
        var clash = Tournament(twice, Path.Combine(Folder, "t2"));
        Assert.Equal(2, clash.ExitCode);
        Assert.Matches("^tournament: --entrants-dir \"[^\"]*\": (a and a.cs|a.cs and a) both make the entrant a; rename one. Usage: ", clash.Stderr);

        var missing = Tournament(Path.Combine(Folder, "nowhere"), Path.Combine(Folder, "t3"));
        Assert.Equal(2, missing.ExitCode);
        Assert.StartsWith("tournament: --entrants-dir must be a folder, got ", missing.Stderr, StringComparison.Ordinal);
    }

    // An entrant's version in the results' header.
    private static string VersionOf(string tour, string name)
    {
        using var header = System.Text.Json.JsonDocument.Parse(File.ReadLines(Path.Combine(tour, "results.jsonl")).First());
        return header.RootElement.GetProperty("entrants").EnumerateArray().Single(e => e.GetProperty("name").GetString() == name).GetProperty("version").GetString()!;
    }
}
