namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Teams are named by their strategy's own name (the SDK's TeamName, the original's GetTeamName())
/// with the spec beside it, in the summary, the trace and the result file; a folder spec may end
/// with a slash; <c>demo</c> is the item's demo strategy.
/// </summary>
public sealed class TeamNameTests() : TempFolderTest("urwpg-team-name-")
{
    [Theory]
    [InlineData("chase-ball", "chase-ball")]
    [InlineData("remote:7000", "remote:7000")]
    [InlineData("teams/red", "red")]
    [InlineData("teams/red/", "red")]
    [InlineData("teams/red//", "red")]
    [InlineData("bin/Release/net10.0/Sharks.Strategy.dll", "Sharks.Strategy.dll")]
    [InlineData("bin/Release/net10.0/Sharks.Strategy.dll#My.Type", "Sharks.Strategy.dll#My.Type")]
    public void ASpecIsShownByItsLastPart(string spec, string shown) => Assert.Equal(shown, TeamName.OfSpec(spec));

    [Fact]
    public void TheCurrentFolderIsShownByItsName()
    {
        Assert.Equal(Path.GetFileName(Environment.CurrentDirectory.TrimEnd('/')), TeamName.OfSpec("."));
        Assert.Equal(Path.GetFileName(Environment.CurrentDirectory.TrimEnd('/')), TeamName.OfSpec("./"));
    }

    [Theory]
    [InlineData(null, null)]
    [InlineData("   ", null)]
    [InlineData("Team First", "Team First")]
    [InlineData("  two\nlines\t", "two lines")]
    [InlineData("a\u2028b", "a b")]
    public void ANameIsOneShortLine(string? raw, string? shown) => Assert.Equal(shown, TeamName.Clean(raw));

    [Fact]
    public void ALongNameIsCut()
    {
        string name = TeamName.Clean(new string('x', 10_000))!;
        Assert.Equal(TeamName.MaximumLength + 3, name.Length);
        Assert.EndsWith("...", name, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(null, "red", "red")]
    [InlineData("red", "red", "red")]
    [InlineData("Team First", "red", "Team First [red]")]
    public void TheLabelPutsTheSpecBesideTheName(string? name, string spec, string label) => Assert.Equal(label, TeamName.Label(name, spec));

    [Fact]
    public void AnOriginalStrategyInAFolderWithATrailingSlashIsNamedByGetTeamNameEverywhere()
    {
        string red = Path.Combine(Folder, "red");
        Directory.CreateDirectory(red);
        string source = File.ReadAllText(Path.Combine(Docs.Repository.PathOf("templates/Strategy"), "Strategy.cs"));
        File.WriteAllText(Path.Combine(red, "Strategy.cs"), source.Replace("\"My Team\"", "\"Team First\"", StringComparison.Ordinal));
        string trace = Path.Combine(Folder, "t.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--cycles", "20", "--strategy", "0=" + red + "/", "--strategy", "1=chase-ball", "--trace", trace);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("score: team 0 (Team First [red]) 0, team 1 (chase-ball) 0\n", run.Stdout, StringComparison.Ordinal);
        using var first = JsonDocument.Parse(File.ReadLines(trace).First());
        var teams = first.RootElement.GetProperty("layout").GetProperty("teams");
        Assert.Equal("Team First [red]", teams[0].GetProperty("name").GetString());
        Assert.Equal("chase-ball", teams[1].GetProperty("name").GetString());

        string results = Path.Combine(Folder, "r.jsonl");
        var batch = CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--cycles", "10", "--batch", "1", "--threads", "1", "--strategy", "0=" + red + "/", "--results", results);
        Assert.Equal(0, batch.ExitCode);
        using var header = JsonDocument.Parse(File.ReadLines(results).First());
        Assert.Equal("Team First [red];ball-grab demo", header.RootElement.GetProperty("teams").GetString());
        Assert.Contains("goals team 0 (Team First [red])", batch.Stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("gb18030")]
    [InlineData("utf-8")]
    [InlineData("utf-8-bom")]
    [InlineData("utf-16")]
    public void An_original_source_saved_in_GBK_as_VS2008_saved_it_keeps_its_Chinese_team_name(string encoding)
    {
        System.Text.Encoding.RegisterProvider(System.Text.CodePagesEncodingProvider.Instance);
        string folder = Path.Combine(Folder, "old-" + encoding);
        Directory.CreateDirectory(folder);
        string source = File.ReadAllText(Path.Combine(Docs.Repository.PathOf("templates/Strategy"), "Strategy.cs"))
            .Replace("\"My Team\"", "\"蓝鲨队\" /* 中文注释：抢球 */", StringComparison.Ordinal);
        byte[] bytes = encoding switch
        {
            "gb18030" => System.Text.Encoding.GetEncoding(936).GetBytes(source), // GBK: what VS2008 wrote on a Chinese Windows
            "utf-8" => new System.Text.UTF8Encoding(false).GetBytes(source),
            "utf-8-bom" => [.. System.Text.Encoding.UTF8.GetPreamble(), .. System.Text.Encoding.UTF8.GetBytes(source)],
            _ => [.. System.Text.Encoding.Unicode.GetPreamble(), .. System.Text.Encoding.Unicode.GetBytes(source)],
        };
        File.WriteAllBytes(Path.Combine(folder, "Strategy.cs"), bytes);
        URWPGSim2D.Hosting.CompiledImages.Forget();
        var run = CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--cycles", "5", "--strategy", "0=" + folder, "--strategy", "1=idle");
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains($"score: team 0 (蓝鲨队 [old-{encoding}]) ", run.Stdout, StringComparison.Ordinal);
        string note = $"{Path.Combine(folder, "Strategy.cs")} is not UTF-8: read as GB18030 (GBK, as Visual Studio 2008 saved Chinese sources); save it as UTF-8 to be sure\n";
        if (encoding == "gb18030")
        {
            Assert.Contains(note, run.Stderr, StringComparison.Ordinal);
        }
        else
        {
            Assert.DoesNotContain("is not UTF-8", run.Stderr, StringComparison.Ordinal);
        }
    }

    [Fact]
    public void DemoIsTheItemsDemoStrategyAndNeedsAnItem()
    {
        var run = CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--cycles", "10", "--strategy", "0=demo", "--strategy", "1=chase-ball");
        Assert.Equal(0, run.ExitCode);
        Assert.Matches(@"\nscore: team 0 \(ball-grab demo\) [0-9]+, team 1 \(chase-ball\) [0-9]+\n", run.Stdout);
        var none = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "10", "--strategy", "0=demo");
        Assert.Equal(2, none.ExitCode);
        Assert.Equal("run: --strategy 0: demo is the demo strategy of a competition item, and this scene is not one (give --item NAME)\n", none.Stderr);
        Assert.Equal(string.Empty, none.Stdout);
    }
}
