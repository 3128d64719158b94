namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary><c>run --strategy TEAM=SPEC</c> end to end: compile errors before the match, faults in the summary, built-in names.</summary>
public sealed class StrategyCliTests() : TempFolderTest("urwpg-cli-strategy-")
{
    [Fact]
    public void CompileErrorsAreFileLineColumnLinesAndExitTwoBeforeTheMatch()
    {
        string red = Path.Combine(Folder, "teams", "red");
        Directory.CreateDirectory(red);
        File.Copy(Path.Combine(OriginalStrategyTests.Folder("Broken"), "Strategy.cs"), Path.Combine(red, "Strategy.cs"));
        string trace = Path.Combine(Folder, "t.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy", "0=" + red, "--trace", trace);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.False(File.Exists(trace), "nothing is written when the strategy does not compile");
        string prefix = Folder + Path.DirectorySeparatorChar;
        string[] expected =
        [
            "compiling teams/red (1 file)...",
            "--strategy 0: cannot compile teams/red: likely cause: Mission.NoSuchMember is a part of the original's API this simulator does not provide (CS1061); use the members docs/strategies.md lists, or report the missing one",
            "teams/red/Strategy.cs(14,21): error CS0103: The name 'undefinedThing' does not exist in the current context",
            "teams/red/Strategy.cs(15,28): error CS1061: 'Mission' does not contain a definition for 'NoSuchMember' and no accessible extension method 'NoSuchMember' accepting a first argument of type 'Mission' could be found (are you missing a using directive or an assembly reference?)",
            "2 compile errors in 1 file",
        ];
        Assert.Equal(expected, run.Stderr.Replace(prefix, string.Empty, StringComparison.Ordinal).TrimEnd('\n').Split('\n'));
        Assert.Equal(string.Join('\n', expected), DocsBlock("compiling teams/red"));
    }

    [Fact]
    public void FaultsOfARealHangAreListedAndTheMatchPlaysToTheEnd()
    {
        // Cycles 5–9 throw, 10–14 answer no decisions, in 20 the strategy sleeps forever: given up
        // when its 1 s bank is spent, then idle. The counts do not depend on timing.
        var run = CliRun.Of(string.Empty, "run", "--cycles", "25", "--strategy", "0=" + OriginalStrategyTests.Folder("Faulty"), "--strategy-timeout", "20", "--time-bank", "1");
        Assert.Equal(0, run.ExitCode);
        Assert.StartsWith("match: 25 cycles,", run.Stdout, StringComparison.Ordinal);
        string line = "  team 0 (Faulty): 5 exceptions, 1 timeouts, 5 bad answers, out of time in cycle 20; its fish kept their last decisions until then and stopped after; first: cycle 5: InvalidOperationException: faulty on purpose";
        Assert.Contains("strategy faults:\n" + line + "\n", run.Stdout, StringComparison.Ordinal);
        Assert.Equal("strategy faults:\n" + line, DocsBlock("strategy faults:"));
    }

    [Fact]
    public void BuiltInNamesAndUnknownSpecs()
    {
        var idle = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy", "1=idle");
        Assert.Equal(0, idle.ExitCode);
        Assert.Contains("team 1 (idle)", idle.Stdout, StringComparison.Ordinal);
        var bad = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy", "1=nonsense");
        Assert.Equal(2, bad.ExitCode);
        Assert.Equal("--strategy 1: \"nonsense\" is not a built-in strategy (idle, chase-ball), a .dll, a .cs file or a folder\n", bad.Stderr);
        var none = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy", "1=" + Folder);
        Assert.Equal(2, none.ExitCode);
        Assert.Equal($"--strategy 1: no .cs files in {Folder}\n", none.Stderr);
    }

    [Fact]
    public void AnSdkStrategyCompilesFromASingleSourceFile()
    {
        string file = Path.Combine(Folder, "Sprinter.cs");
        File.WriteAllText(file, StrategyLoaderTests.SprinterSource);
        var run = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy", "0=" + file, "--strategy", "1=" + file);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("team 0 (sprinters [Sprinter.cs])", run.Stdout, StringComparison.Ordinal);

        // Progress while waiting: a line when compiling starts and one when it is done, on stderr,
        // once for the two teams of the same source (the summary on stdout is unchanged).
        string[] progress = [.. run.Stderr.Split('\n').Where(l => l.StartsWith("compil", StringComparison.Ordinal))];
        Assert.Equal(2, progress.Length);
        Assert.Equal($"compiling {file} (1 file)...", progress[0]);
        Assert.Matches("^compiled " + System.Text.RegularExpressions.Regex.Escape(file) + " in [0-9]+\\.[0-9] s$", progress[1]);
        Assert.DoesNotContain("compil", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("strategy faults: none", run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void TheSensingSampleSeesTheMatchWithoutFaults()
    {
        // The docs' FieldSensor sample, compiled from source and played for 100 cycles of ball-grab.
        string sample = Docs.Repository.PathOf("samples/URWPGSim2D.Strategy.Samples/SensingStrategy.cs");
        var run = CliRun.Of(string.Empty, "run", "--cycles", "100", "--strategy", "0=" + sample);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("team 0 (look before swimming [SensingStrategy.cs])", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("strategy faults: none", run.Stdout, StringComparison.Ordinal);
    }

    // The text of the docs/strategies.md code block starting with the given line.
    private static string DocsBlock(string firstLine)
    {
        string text = File.ReadAllText(Docs.Repository.PathOf("docs/strategies.md")).Replace("\r\n", "\n", StringComparison.Ordinal);
        int start = text.IndexOf("```\n" + firstLine, StringComparison.Ordinal);
        Assert.True(start >= 0, $"docs/strategies.md has a block starting with {firstLine}");
        start += 4;
        int end = text.IndexOf("\n```", start, StringComparison.Ordinal);
        return text[start..end];
    }
}
