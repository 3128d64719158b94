namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// Tournament entrants run as <c>run</c>'s strategies do: each user entrant in a fresh strategy host
/// per match by default, in the server's process with <c>--isolation none</c>. Well-behaved entrants
/// give the same bytes either way and on any number of threads; hostile ones (written in the
/// original's API) fault, are charged in their matches' results, and every match is played.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class TournamentIsolationTests() : TempFolderTest("urwpg-tour-iso-")
{
    private string Dir(string name) => Path.Combine(Folder, name);

    private static string[] Lines(string folder) => File.ReadAllLines(Path.Combine(folder, "results.jsonl"));

    [Fact]
    public void Hosted_and_in_process_entrants_give_the_same_bytes()
    {
        string sample = Repository.PathOf("samples/URWPGSim2D.Strategy.Samples/SdkStrategy.cs");
        string pusher = Repository.PathOf("samples/URWPGSim2D.Strategy.Samples/OriginalApiStrategy.cs");
        string[] tour = ["tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "sdk=" + sample, "--entrant", "original=" + pusher, "--seeds", "1", "--cycles", "40", "--strategy-timeout", "5000"];
        var hosted = CliRun.Of(string.Empty, [.. tour, "--threads", "2", "--sandbox", "required", "--out", Dir("hosted")]);
        Assert.True(hosted.ExitCode == 0, hosted.Stderr);
        var inProcess = CliRun.Of(string.Empty, [.. tour, "--threads", "1", "--isolation", "none", "--out", Dir("none")]);
        Assert.True(inProcess.ExitCode == 0, inProcess.Stderr);
        foreach (string file in new[] { "results.jsonl", "standings.json", "standings.md", "report.html" })
        {
            Assert.Equal(File.ReadAllBytes(Path.Combine(Dir("none"), file)), File.ReadAllBytes(Path.Combine(Dir("hosted"), file)));
        }

        Assert.Equal(7, Lines(Dir("hosted")).Length); // header + 3 × 2 matches
        Assert.DoesNotContain(Lines(Dir("hosted")), l => l.Contains("\"faults\"", StringComparison.Ordinal) || l.Contains("forfeit", StringComparison.Ordinal));
    }

    [Fact]
    public void Hostile_entrants_are_charged_in_their_matches_and_every_match_is_played()
    {
        string overflow = OriginalSource.Write(Folder, "Overflow", "if (cycle == 2) Recurse(0);", "static int Recurse(int n) { return Recurse(n + 1) + 1; }");
        string badCtor = OriginalSource.Write(Folder, "BadCtor", "", "public Strategy() { throw new InvalidOperationException(\"no team today\"); }");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "overflow=" + overflow, "--entrant", "ctor=" + badCtor,
            "--seeds", "1", "--cycles", "20", "--strategy-timeout", "5000", "--threads", "2", "--sandbox", "required", "--out", Dir("t"));
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.DoesNotContain("cannot be loaded", run.Stderr, StringComparison.Ordinal);
        string[] matches = Lines(Dir("t")).Skip(1).ToArray();
        Assert.Equal(6, matches.Length);
        foreach (string line in matches)
        {
            Assert.DoesNotContain("forfeit", line, StringComparison.Ordinal);
            Assert.Contains("\"cycles\":20,", line, StringComparison.Ordinal);
        }

        // Every match of the overflowing entrant charges its host's end in cycle 3 to its team; every match of the other, its constructor in cycle 1.
        int overflows = matches.Count(l => l.Contains("\"crashes\":1,\"first\":\"cycle 3: strategy host ended: ", StringComparison.Ordinal));
        int constructors = matches.Count(l => l.Contains("\"crashes\":1,\"first\":\"cycle 1: strategy host ended: exit code 4: cannot create strategy URWPGSim2D.Strategy.Strategy", StringComparison.Ordinal)
            && l.Contains("no team today", StringComparison.Ordinal));
        Assert.Equal(4, overflows);
        Assert.Equal(4, constructors);
        string standings = File.ReadAllText(Path.Combine(Dir("t"), "standings.json"));
        Assert.Contains("\"name\": \"overflow\"", standings, StringComparison.Ordinal);
        Assert.DoesNotContain("\"error\"", standings, StringComparison.Ordinal);
    }

    [Fact]
    public void In_process_a_throwing_constructor_is_a_fault_of_the_match_not_a_forfeit()
    {
        string badCtor = OriginalSource.Write(Folder, "BadStatic", "", "static readonly int Never = int.Parse(\"not a number\"); public Strategy() { _ = Never; }");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "ctor=" + badCtor,
            "--seeds", "1", "--cycles", "10", "--strategy-timeout", "5000", "--isolation", "none", "--out", Dir("n"));
        Assert.True(run.ExitCode == 0, run.Stderr);
        string[] matches = Lines(Dir("n")).Skip(1).ToArray();
        Assert.Equal(2, matches.Length);
        foreach (string line in matches)
        {
            Assert.Contains("\"crashes\":1,\"first\":\"cycle 1: cannot create strategy URWPGSim2D.Strategy.Strategy from ", line, StringComparison.Ordinal);
            Assert.Contains("(FormatException: ", line, StringComparison.Ordinal);
        }
    }

    [Theory]
    [InlineData("--isolation", "thread", "tournament: --isolation must be process or none, got \"thread\"")]
    [InlineData("--sandbox", "maybe", "tournament: --sandbox must be auto, required or off, got \"maybe\"")]
    [InlineData("--strategy-memory", "8", "tournament: --strategy-memory must be an integer 64..1048576, got \"8\"")]
    public void Hosting_options_are_checked_like_runs(string option, string value, string message)
    {
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "a=idle", "--entrant", "b=idle", option, value, "--out", Dir("bad"));
        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith(message + ". Usage: ", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
        Assert.False(Directory.Exists(Dir("bad")));
    }
}
