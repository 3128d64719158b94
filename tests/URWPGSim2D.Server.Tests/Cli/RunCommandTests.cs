namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>The run command: summary, trace, SVG, bad input.</summary>
public sealed class RunCommandTests() : TempFolderTest("urwpg-run-")
{
    [Fact]
    public void TheOldDefaultMatchPrintsTheSummary()
    {
        var run = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "50");
        Assert.Equal(0, run.ExitCode);
        Assert.Equal(string.Empty, run.Stderr);
        string[] lines = run.Stdout.TrimEnd('\n').Split('\n');
        Assert.Equal(6, lines.Length);
        Assert.Matches(@"^match: 50 cycles, 5\.0 s simulated in [0-9.]+ ms wall time \([0-9]+x real time, [0-9.]+ us per cycle\), seed [0-9]+$", lines[0]);
        Assert.Matches(@"^goals: team 0 \(chase-ball\) [0-9]+, team 1 \(chase-ball\) [0-9]+$", lines[1]);
        Assert.Matches(@"^contacts: fish-fish [0-9]+, fish-ball [0-9]+, fish-obstacle [0-9]+, fish-border [0-9]+, ball-ball [0-9]+, ball-obstacle [0-9]+, ball-border [0-9]+$", lines[2]);
        Assert.Matches(@"^sub-steps: [0-9]+ \(at most [0-9]+ in one cycle\), contact events: [0-9]+$", lines[3]);
        Assert.Matches(@"^largest leftover overlap: 0\.[0-9]{3} mm", lines[4]);
        Assert.Equal("strategy faults: none", lines[5]);
    }

    [Fact]
    public void TraceIsJsonLinesFromCycleZeroAndSvgIsWritten()
    {
        string scenario = Path.Combine(Folder, "s.json");
        File.WriteAllText(scenario, """
            {"cycles": 30, "noise": false,
             "fish": [{"team":0,"position":[-300,0],"decision":{"vcode":15,"tcode":7}}],
             "balls": [{"position":[0,0]}],
             "obstacles": [{"type":"round","center":[0,400],"radius":50}]}
            """);
        string trace = Path.Combine(Folder, "t.jsonl");
        string svg = Path.Combine(Folder, "f.svg");
        var run = CliRun.Of(string.Empty, "run", "--scenario", scenario, "--trace", trace, "--svg", svg);
        Assert.Equal(0, run.ExitCode);

        string[] lines = File.ReadAllLines(trace);
        Assert.Equal(31, lines.Length);
        bool sawFishBall = false;
        for (int k = 0; k < lines.Length; k++)
        {
            using var doc = JsonDocument.Parse(lines[k]);
            var root = doc.RootElement;
            Assert.Equal(k, root.GetProperty("cycle").GetInt32());
            var fish = root.GetProperty("fish")[0];
            Assert.Equal(2, fish.GetProperty("position").GetArrayLength());
            Assert.Equal(3, fish.GetProperty("joints").GetArrayLength());
            Assert.Equal(JsonValueKind.Number, fish.GetProperty("heading").ValueKind);
            Assert.Equal(JsonValueKind.Number, fish.GetProperty("speed").ValueKind);
            Assert.Equal(JsonValueKind.Number, fish.GetProperty("angularSpeed").ValueKind);
            Assert.Equal(2, root.GetProperty("balls")[0].GetProperty("velocity").GetArrayLength());
            foreach (var c in root.GetProperty("contacts").EnumerateArray())
            {
                if (c.GetProperty("a").GetString() == "fish0" && c.GetProperty("b").GetString() == "ball0")
                {
                    sawFishBall = true;
                    Assert.Equal(JsonValueKind.String, c.GetProperty("partA").ValueKind);
                    Assert.Equal(JsonValueKind.Null, c.GetProperty("partB").ValueKind);
                    Assert.Equal(2, c.GetProperty("mtv").GetArrayLength());
                    Assert.Equal(2, c.GetProperty("normal").GetArrayLength());
                    Assert.Equal(2, c.GetProperty("actionPoint").GetArrayLength());
                }
            }
        }

        Assert.True(sawFishBall, "the fish hit the ball");
        Assert.Empty(Directory.GetFiles(Folder, "*.partial"));
        string picture = File.ReadAllText(svg);
        Assert.StartsWith("<svg xmlns=\"http://www.w3.org/2000/svg\"", picture, StringComparison.Ordinal);
        Assert.Equal(8, CountOf(picture, "<polygon") - 0);
        Assert.Contains("cycle 30", picture, StringComparison.Ordinal);
    }

    [Fact]
    public void ABadScenarioIsOneLineExitTwoAndNoFileWritten()
    {
        string scenario = Path.Combine(Folder, "bad.json");
        File.WriteAllText(scenario, """{"fish":[],"balls":[{"position":[0,0]},{"position":[300,0]},{"position":[0,300],"radius":-5}]}""");
        string trace = Path.Combine(Folder, "t.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--scenario", scenario, "--trace", trace);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.Equal("balls[2].radius: must be > 0, got -5\n", run.Stderr);
        Assert.Empty(Directory.GetFiles(Folder, "t.jsonl*"));
    }

    [Theory]
    [InlineData(new[] { "run", "--cycles", "many" }, "run: --cycles must be an integer 0..2147483647, got \"many\"")]
    [InlineData(new[] { "run", "--cycles" }, "run: --cycles needs a value")]
    [InlineData(new[] { "run", "--fast", "1" }, "run: unknown option \"--fast\"")]
    [InlineData(new[] { "run", "--strategy", "4=x.dll" }, "run: --strategy must be TEAM=SPEC with TEAM 0 to 3, got \"4=x.dll\"")]
    [InlineData(new[] { "run", "--seed", "1", "--seed", "2" }, "run: --seed given twice")]
    public void BadArgumentsAreOneUsageLine(string[] args, string start)
    {
        var run = CliRun.Of(string.Empty, args);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.StartsWith(start + ". Usage: urwpgsim2d run [--item NAME | --scenario FILE | --crowd N] [--minutes 10|5|3|1 | --cycles N]", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
    }

    [Fact]
    public void AMissingStrategyAssemblyIsOneLine()
    {
        var run = CliRun.Of(string.Empty, "run", "--cycles", "1", "--strategy", "1=missing/Team.dll");
        Assert.Equal(2, run.ExitCode);
        Assert.Equal("--strategy 1: strategy assembly not found: missing/Team.dll\n", run.Stderr);
    }

    [Fact]
    public void ALoadedStrategyTakesOverItsTeam()
    {
        string dll = Hosting.StrategyAssemblyBuilder.Build("Sprinters", Hosting.StrategyLoaderTests.SprinterSource);
        var run = CliRun.Of(string.Empty, "run", "--cycles", "20", "--strategy", "1=" + dll);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("team 1 (sprinters [Sprinters.dll])", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("strategy faults: none", run.Stdout, StringComparison.Ordinal);
    }

    private static int CountOf(string text, string part)
    {
        int n = 0;
        for (int i = text.IndexOf(part, StringComparison.Ordinal); i >= 0; i = text.IndexOf(part, i + 1, StringComparison.Ordinal))
        {
            n++;
        }

        return n;
    }
}
