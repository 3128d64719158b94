namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// <c>tournament</c> end to end (in process, short matches): the same bytes on 1 and 2 threads and
/// after merging shards; a re-run plays only what is missing or broken; an entrant that cannot be
/// loaded forfeits; bad input is one line and exit code 2 before anything is written.
/// </summary>
public sealed class TournamentCommandTests() : TempFolderTest("urwpg-tournament-")
{
    private static readonly string[] Files = ["results.jsonl", "standings.json", "standings.md", "report.html"];

    private string[] Base(string item = "ball-grab") =>
        ["tournament", "--item", item, "--entrant", "demo=demo", "--entrant", "chase=chase-ball", "--entrant", "idle=idle", "--seeds", "2", "--cycles", "80"];

    private CliRun Run(params string[] extra) => CliRun.Of(string.Empty, [.. Base(), .. extra]);

    private string Dir(string name) => Path.Combine(Folder, name);

    [Fact]
    public void OneAndTwoThreadsAndMergedShardsGiveTheSameBytes()
    {
        var one = Run("--threads", "1", "--out", Dir("one"));
        Assert.True(one.ExitCode == 0, one.Stderr);
        Assert.StartsWith("tournament: ball-grab, 3 entrants, 2 seeds, 12 matches; 12 to play, 0 already there\n", one.Stdout, StringComparison.Ordinal);
        var two = Run("--threads", "2", "--out", Dir("two"));
        Assert.True(two.ExitCode == 0, two.Stderr);

        // Three shards, then the merge of their files into a fourth folder.
        var shards = new List<string>();
        for (int i = 0; i < 3; i++)
        {
            string file = Path.Combine(Folder, $"shard-{i}.jsonl");
            var shard = Run("--out", Dir("merged"), "--shard", $"{i}/3", "--results", file);
            Assert.True(shard.ExitCode == 0, shard.Stderr);
            Assert.Contains($"shard {i}/3 finished: 4 of 4 matches", shard.Stdout, StringComparison.Ordinal);
            shards.Add(file);
        }

        Assert.False(Directory.Exists(Dir("merged")) && File.Exists(Path.Combine(Dir("merged"), "standings.json")));
        var merged = CliRun.Of(string.Empty, [.. Base(), "--out", Dir("merged"), "--merge", .. shards]);
        Assert.True(merged.ExitCode == 0, merged.Stderr);
        Assert.Contains("0 to play, 12 already there", merged.Stdout, StringComparison.Ordinal);
        foreach (string file in Files)
        {
            byte[] reference = File.ReadAllBytes(Path.Combine(Dir("one"), file));
            Assert.Equal(reference, File.ReadAllBytes(Path.Combine(Dir("two"), file)));
            Assert.Equal(reference, File.ReadAllBytes(Path.Combine(Dir("merged"), file)));
        }

        string json = File.ReadAllText(Path.Combine(Dir("one"), "standings.json"));
        Assert.StartsWith("{\n  \"item\": \"ball-grab\",\n  \"matches\": 12,\n  \"entrants\": [\n    {\"name\": ", json, StringComparison.Ordinal);
        Assert.Matches("\"rank\": 1, \"rating\": [0-9.]+, \"ci\": \\[[0-9.]+, [0-9.]+\\], \"played\": 8, \"wins\": [0-9]+, \"draws\": [0-9]+, \"losses\": [0-9]+\\}", json);
    }

    [Fact]
    public void ARerunPlaysOnlyMissingAndBrokenMatches()
    {
        Assert.Equal(0, Run("--out", Dir("t")).ExitCode);
        string results = Path.Combine(Dir("t"), "results.jsonl");
        var reference = Files.ToDictionary(f => f, f => File.ReadAllBytes(Path.Combine(Dir("t"), f)));

        var again = Run("--out", Dir("t"));
        Assert.Contains("; 0 to play, 12 already there\n", again.Stdout, StringComparison.Ordinal);

        // Lines 3 and 5 (matches 1 and 3) gone, match 6's line garbled, the last line cut short.
        var lines = File.ReadAllLines(results).ToList();
        lines[7] = lines[7][..20] + "}";
        string cut = lines[^1][..30];
        lines.RemoveAt(lines.Count - 1);
        lines.RemoveAt(4);
        lines.RemoveAt(2);
        File.WriteAllText(results, string.Join('\n', lines) + "\n" + cut);
        var resumed = Run("--out", Dir("t"));
        Assert.True(resumed.ExitCode == 0, resumed.Stderr);
        Assert.Contains("; 4 to play, 8 already there, 2 broken lines dropped\n", resumed.Stdout, StringComparison.Ordinal);
        foreach (var (file, bytes) in reference)
        {
            Assert.Equal(bytes, File.ReadAllBytes(Path.Combine(Dir("t"), file)));
        }
    }

    [Fact]
    public void AnEntrantThatDoesNotCompileForfeitsAndTheTournamentFinishes()
    {
        string bad = Path.Combine(Folder, "Bad.cs");
        File.WriteAllText(bad, "public class Broken {");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "bad=" + bad, "--entrant", "idle=idle", "--seeds", "1", "--cycles", "40", "--out", Dir("f"));
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("tournament: entrant bad cannot be loaded and forfeits its matches: cannot compile", run.Stderr, StringComparison.Ordinal);
        string json = File.ReadAllText(Path.Combine(Dir("f"), "standings.json"));
        Assert.Contains("{\"name\": \"bad\", \"rank\": 3, ", json, StringComparison.Ordinal);
        Assert.Contains("\"played\": 4, \"wins\": 0, \"draws\": 0, \"losses\": 4, \"error\": \"cannot compile", json, StringComparison.Ordinal);
        Assert.Contains("\"kind\":\"forfeit\"", File.ReadAllText(Path.Combine(Dir("f"), "results.jsonl")), StringComparison.Ordinal);
        Assert.Contains("- bad: cannot compile", File.ReadAllText(Path.Combine(Dir("f"), "standings.md")), StringComparison.Ordinal);

        // Mended, the entrant's forfeits are played on the next run; the others stay.
        File.WriteAllText(bad, "public sealed class Mended : URWPGSim2D.Strategies.IStrategy { public string TeamName => \"mended\"; public void Decide(URWPGSim2D.Strategies.MatchSnapshot s, System.ReadOnlySpan<int> f, System.Span<URWPGSim2D.Strategies.Decision> d) { } }");
        var mended = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "bad=" + bad, "--entrant", "idle=idle", "--seeds", "1", "--cycles", "40", "--out", Dir("f"));
        Assert.True(mended.ExitCode == 0, mended.Stderr);
        Assert.Contains("; 4 to play, 2 already there, 4 matches of changed or removed entrants dropped\n", mended.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("error", File.ReadAllText(Path.Combine(Dir("f"), "standings.json")), StringComparison.Ordinal);
    }

    [Fact]
    public void AOneTeamItemRanksByMeanScore()
    {
        var run = CliRun.Of(string.Empty, "tournament", "--item", "transport", "--entrant", "demo=demo", "--entrant", "idle=idle", "--seeds", "2", "--cycles", "50", "--out", Dir("one"), "--replays");
        Assert.True(run.ExitCode == 0, run.Stderr);
        string json = File.ReadAllText(Path.Combine(Dir("one"), "standings.json"));
        Assert.Matches("\\{\"name\": \"(demo|idle)\", \"rank\": 1, \"score\": [0-9.]+, \"ci\": \\[[0-9.]+, [0-9.]+\\], \"played\": 2, \"seconds\": 5\\}", json);
        string report = File.ReadAllText(Path.Combine(Dir("one"), "report.html"));
        for (int j = 0; j < 4; j++)
        {
            Assert.True(File.Exists(Path.Combine(Dir("one"), "replays", $"match-{j}.html")));
            Assert.Contains($"<a href=\"replays/match-{j}.html\">replay</a>", report, StringComparison.Ordinal);
        }

        Assert.Contains("<svg", report, StringComparison.Ordinal);
        Assert.DoesNotContain("<script", report, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--item", "football", "--item must be one of")]
    [InlineData("--seeds", "0", "--seeds must be an integer 1..100000, got \"0\"")]
    [InlineData("--minutes", "7", "--minutes must be 10, 5, 3 or 1, got \"7\"")]
    [InlineData("--entrant", "chase=nowhere/Mine.cs", "--entrant chase: \"nowhere/Mine.cs\" is not demo, a built-in strategy")]
    [InlineData("--entrant", "x", "--entrant must be NAME=SPEC")]
    [InlineData("--entrant", "demo=idle", "--entrant: the name \"demo\" is given twice")]
    [InlineData("--shards", "3", "--shards, --partition, --time, --sbatch-arg, --slurm-setup and --submit belong to --slurm SDIR")]
    [InlineData("--seed", "9223372036854775807", "--seeds 2 --seed 9223372036854775807: seeds from 9223372036854775807 would go beyond 9223372036854775807")]
    public void BadInputIsOneLineAndExitCode2BeforeAnythingIsWritten(string option, string value, string message)
    {
        var args = Base().ToList();
        int at = args.IndexOf(option);
        if (at >= 0 && option != "--entrant")
        {
            args[at + 1] = value;
        }
        else
        {
            args.AddRange([option, value]);
        }

        var run = CliRun.Of(string.Empty, [.. args, "--out", Dir("bad")]);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.Contains(message, run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
        Assert.False(Directory.Exists(Dir("bad")));
    }

    [Fact]
    public void AnotherTournamentsResultsAreNeverOverwritten()
    {
        Assert.Equal(0, Run("--out", Dir("t")).ExitCode);
        string results = Path.Combine(Dir("t"), "results.jsonl");
        byte[] before = File.ReadAllBytes(results);
        var other = CliRun.Of(string.Empty, [.. Base(), "--seed", "5", "--out", Dir("t")]);
        Assert.Equal(2, other.ExitCode);
        Assert.Contains("holds another tournament (first seed 1 vs 5); use another --out or delete it", other.Stderr, StringComparison.Ordinal);
        Assert.Equal(before, File.ReadAllBytes(results));

        File.WriteAllText(Path.Combine(Folder, "note.txt"), "mine");
        var notEmpty = Run("--out", Folder);
        Assert.Equal(2, notEmpty.ExitCode);
        Assert.Contains("is not empty and holds no results.jsonl", notEmpty.Stderr, StringComparison.Ordinal);
    }
}
