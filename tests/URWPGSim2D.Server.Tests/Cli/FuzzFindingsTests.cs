using URWPGSim2D.Engine.Messages;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// The failures the fuzzing of issue 15 found, each pinned: every one is now a single stderr
/// line, exit code 2, nothing on stdout and no file written.
/// </summary>
public sealed class FuzzFindingsTests() : TempFolderTest("urwpg-findings-")
{
    private const string Header =
        "{\"kind\":\"batch\",\"scene\":\"default\",\"strategies\":\"\",\"teams\":\"chase-ball;chase-ball\",\"noise\":\"scenario\"," +
        "\"strategyTimeoutMs\":100,\"firstSeed\":1,\"matches\":1,\"cycles\":5,\"shard\":0,\"shards\":1}";

    private const string Match =
        "{\"kind\":\"match\",\"index\":0,\"seed\":1,\"cycles\":5,\"goals\":GOALS,\"contacts\":{\"fish-fish\":0,\"fish-ball\":0," +
        "\"fish-obstacle\":0,\"fish-border\":0,\"ball-ball\":0,\"ball-obstacle\":0,\"ball-border\":0},\"subSteps\":5," +
        "\"mostSubSteps\":1,\"events\":0,\"leftoverOverlap\":0,\"leftoverCycle\":0,\"strategyFaults\":0}";

    /// <inheritdoc/>

    [Theory]
    [InlineData("[1]")]
    [InlineData("[]")]
    [InlineData("[1,2,3]")]
    [InlineData("7")]
    public void MergeOfAResultLineWithTheWrongNumberOfGoalsIsOneLine(string goals)
    {
        string file = Path.Combine(Folder, "r.jsonl");
        File.WriteAllText(file, Header + "\n" + Match.Replace("GOALS", goals, StringComparison.Ordinal) + "\n");

        var run = CliRun.Of(string.Empty, "merge", file);

        CollideErrorTests.AssertOneLineFailure(run, $"{file}:2: \"goals\" must be an array of 2 counts (one per team), got {goals}");
    }

    [Fact]
    public void MergeOfAWellFormedFileStillWorks()
    {
        string file = Path.Combine(Folder, "r.jsonl");
        File.WriteAllText(file, Header + "\n" + Match.Replace("GOALS", "[2,1]", StringComparison.Ordinal) + "\n");

        var run = CliRun.Of(string.Empty, "merge", file);

        Assert.Equal(0, run.ExitCode);
        Assert.Contains("batch: 1 matches", run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void AnUnknownScenarioKeyHoldingALineBreakIsEscaped()
    {
        var run = CliRun.Of("{\"fish\":[],\"balls\":[],\"obst\\nacles\":1}", "run", "--scenario", "-");

        CollideErrorTests.AssertOneLineFailure(run, "obst\\nacles: unknown property (expected one of: field, cycles, seed, noise, fish, balls, obstacles)");
    }

    [Fact]
    public void ABatchSceneHoldingALineBreakIsEscapedWhenMergeEchoesIt()
    {
        string a = Path.Combine(Folder, "a.jsonl"), b = Path.Combine(Folder, "b.jsonl");
        string match = Match.Replace("GOALS", "[0,0]", StringComparison.Ordinal);
        File.WriteAllText(a, Header.Replace("\"scene\":\"default\"", "\"scene\":\"x\\ny\\u2028z\"", StringComparison.Ordinal) + "\n" + match + "\n");
        File.WriteAllText(b, Header + "\n" + match + "\n");

        var run = CliRun.Of(string.Empty, "merge", a, b);

        CollideErrorTests.AssertOneLineFailure(run, $"{b}: belongs to another batch than {a} (scene x\\ny\\u2028z vs default)");
    }

    [Fact]
    public void ALoneSurrogateInAScenarioStringIsBadInput()
    {
        var run = CliRun.Of("{\"fish\":[{\"team\":0,\"position\":[0,0],\"strategy\":\"\\ud800\"}],\"balls\":[{\"position\":[0,0]}]}", "run", "--scenario", "-");

        CollideErrorTests.AssertOneLineFailure(run, "fish[0].strategy: must be valid UTF-16 text, got \"\\ud800\" (a lone surrogate)");
    }

    [Fact]
    public void ALoneSurrogateInAScenarioPropertyNameIsBadInput()
    {
        var run = CliRun.Of("{\"fish\":[],\"balls\":[],\"x\\udc00\":1}", "run", "--scenario", "-");

        CollideErrorTests.AssertOneLineFailure(run, "property names must be valid UTF-16 text, got \"x\\udc00\":1 (a lone surrogate)");
    }

    [Theory]
    [InlineData("--svg", "f.svg")]
    [InlineData("--trace", "t.jsonl")]
    public void AnOutputInAMissingFolderFailsBeforeTheMatch(string option, string name)
    {
        string missing = Path.Combine(Folder, "missing");
        string path = Path.Combine(missing, name);

        // 30,000 cycles would take minutes: the check must come first.
        var run = CliRun.Of(string.Empty, "run", "--cycles", "30000", option, path);

        CollideErrorTests.AssertOneLineFailure(run, $"{option}: cannot write \"{path}\" (folder \"{missing}\" does not exist)");
        Assert.Empty(Directory.GetFileSystemEntries(Folder));
    }

    [Fact]
    public void AnOutputThatIsAFolderFailsBeforeTheMatch()
    {
        var run = CliRun.Of(string.Empty, "run", "--cycles", "30000", "--svg", Folder);

        CollideErrorTests.AssertOneLineFailure(run, $"--svg: cannot write \"{Folder}\" (it is a folder, give a file name)");
    }

    [Theory]
    [InlineData("a\nb", "a\\nb")]
    [InlineData("tab\there", "tab\\there")]
    [InlineData("cr\r", "cr\\r")]
    [InlineData("nul\0", "nul\\u0000")]
    [InlineData("sep\u2028para\u2029", "sep\\u2028para\\u2029")]
    [InlineData("pair \ud83d\udc1f fish", "pair \ud83d\udc1f fish")]
    [InlineData("plain \\ text é", "plain \\ text é")]
    public void EscapeKeepsEveryMessageOnOneLine(string text, string expected)
    {
        Assert.Equal(expected, MessageText.Escape(text));
    }

    [Fact]
    public void EscapeWritesLoneSurrogatesAsEscapes()
    {
        // Not in InlineData: an attribute's string cannot hold a lone surrogate.
        Assert.Equal("lone \\ud800 high", MessageText.Escape("lone \ud800 high"));
        Assert.Equal("lone \\udc00 low", MessageText.Escape("lone \udc00 low"));
        Assert.Equal("end \\ud83d", MessageText.Escape("end \ud83d"));
        Assert.Equal("\\udc1f\\ud83d", MessageText.Escape("\udc1f\ud83d"));
    }

    [Fact]
    public void ALoneSurrogateInANestedScenarioKeyIsBadInput()
    {
        string json = "{\"fish\":[],\"balls\":[],\n\"obstacles\":[{\"type\":\"rectangle\",\"center\":[0,0],\"\\ud800\":1}]}";

        var run = CliRun.Of(json, "run", "--scenario", "-");

        CollideErrorTests.AssertOneLineFailure(run, "invalid text at line 2, column 49: a lone UTF-16 surrogate escape (\\ud800 to \\udfff without its pair)");
    }

    [Fact]
    public void ALoneSurrogateKeyInARenderInputIsBadInput()
    {
        string svg = Path.Combine(Folder, "f.svg");

        var run = CliRun.Of("[{\"a\":{\"type\":\"circle\",\"center\":[0,0],\"radius\":1},\"\\ud800\":{}}]", "render", "-", "--svg", svg);

        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.Single(run.Stderr.Split('\n', StringSplitOptions.RemoveEmptyEntries));
        Assert.Empty(Directory.GetFileSystemEntries(Folder));
    }

    [Fact]
    public void AHugeRectangleObstacleIsBadInput()
    {
        var run = CliRun.Of("{\"fish\":[],\"balls\":[],\"obstacles\":[{\"type\":\"rectangle\",\"center\":[0,0],\"length\":100,\"width\":9223372036854775808}]}", "run", "--scenario", "-");

        CollideErrorTests.AssertOneLineFailure(run, "obstacles[0].width: must be at most the field's larger side (3000), got 9.223372E+18");
    }

    [Theory]
    [InlineData("1e999")]
    [InlineData("-1")]
    public void MergeRefusesABadOverlapAndLeavesNoPartialFile(string overlap)
    {
        string input = Path.Combine(Folder, "r.jsonl");
        string output = Path.Combine(Folder, "out");
        Directory.CreateDirectory(output);
        File.WriteAllText(input, Header + "\n" + Match.Replace("GOALS", "[0,0]", StringComparison.Ordinal).Replace("\"leftoverOverlap\":0", $"\"leftoverOverlap\":{overlap}", StringComparison.Ordinal) + "\n");

        var run = CliRun.Of(string.Empty, "merge", "--out", Path.Combine(output, "all.jsonl"), input);

        CollideErrorTests.AssertOneLineFailure(run, $"{input}:2: \"leftoverOverlap\" must be a finite number >= 0, got {overlap}");
        Assert.Empty(Directory.GetFileSystemEntries(output));
    }
}
