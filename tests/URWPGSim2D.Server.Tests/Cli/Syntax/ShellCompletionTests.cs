using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Tests.Cli.Syntax;

/// <summary>
/// Tab completion, asked in-process as the shell scripts ask it (<c>[suggest:N] LINE</c>): command
/// names, option names from the declarations, item names with the Chinese names, strategy specs,
/// fixed values and paths.
/// </summary>
public sealed class ShellCompletionTests
{
    [Fact]
    public void AnOptionPrefixCompletesToTheOption()
    {
        Assert.Equal(["--item"], Complete("urwpgsim2d run --it"));
        Assert.Equal(["--entrant", "--entrants-dir"], Complete("urwpgsim2d tournament --ent"));
        Assert.Equal(["--check"], Complete("urwpgsim2d tournament --ch"));
        Assert.Equal(["--svg"], Complete("urwpgsim2d render a.json --s"));
    }

    [Fact]
    public void TheFirstWordCompletesToEveryCommand()
    {
        string[] commands = [.. CliApp.DefaultCommands.Select(c => c.Name)];
        Assert.Equal(commands.Order(StringComparer.Ordinal), Complete("urwpgsim2d ").Where(c => !c.StartsWith('-')).Order(StringComparer.Ordinal));
        Assert.Equal(["tournament"], Complete("urwpgsim2d to"));
        Assert.Empty(Complete("urwpgsim2d")); // the cursor is still in the program's name
    }

    [Fact]
    public void AnItemPrefixListsTheItemsItBegins()
    {
        string[] polo = [.. ItemRegistry.All.Select(i => i.Slug).Where(s => s.StartsWith("polo", StringComparison.Ordinal))];
        Assert.NotEmpty(polo);
        Assert.Equal(polo.Order(StringComparer.Ordinal), Complete("urwpgsim2d run --item po").Order(StringComparer.Ordinal));
        Assert.Equal(polo.Order(StringComparer.Ordinal), Complete("urwpgsim2d tournament --item PO").Order(StringComparer.Ordinal));
    }

    [Fact]
    public void ChineseItemNamesComplete()
    {
        string[] water = [.. ItemRegistry.All.Select(i => i.ChineseName).Where(n => n.StartsWith('水'))];
        Assert.True(water.Length >= 2, string.Join(", ", water));
        Assert.Equal(water.Order(StringComparer.Ordinal), Complete("urwpgsim2d run --item 水").Order(StringComparer.Ordinal));
        Assert.Equal(["水球1VS1"], Complete("urwpgsim2d run --item 水球1vs"));
    }

    [Fact]
    public void AnEmptyItemListsEverySlugAndChineseNameAndRunsDefault()
    {
        var expected = ItemRegistry.All.SelectMany(i => new[] { i.Slug, i.ChineseName }).Append("default").Order(StringComparer.Ordinal);
        Assert.Equal(expected, Complete("urwpgsim2d run --item ").Order(StringComparer.Ordinal));
        Assert.DoesNotContain("default", Complete("urwpgsim2d tournament --item "));
    }

    [Fact]
    public void ATeamOffersTheBuiltInStrategiesAndRemote()
    {
        var offered = Complete("urwpgsim2d run --strategy 0=");
        foreach (string name in StrategyResolver.BuiltInNames.Append("demo").Append("remote:"))
        {
            Assert.Contains("0=" + name, offered);
        }

        Assert.Equal(["3=demo"], Complete("urwpgsim2d run --strategy 3=de"));
        Assert.Equal(["0=", "1=", "2=", "3="], Complete("urwpgsim2d run --strategy "));
        Assert.Contains("red=chase-ball", Complete("urwpgsim2d tournament --entrant red=ch"));
    }

    [Fact]
    public void FixedValuesAreOffered()
    {
        Assert.Equal(["1", "10", "3", "5"], Complete("urwpgsim2d run --minutes ").Order(StringComparer.Ordinal));
        Assert.Equal(["off", "on"], Complete("urwpgsim2d run --noise o").Order(StringComparer.Ordinal));
        Assert.Equal(["required"], Complete("urwpgsim2d tournament --sandbox r"));
        Assert.Equal(["bash"], Complete("urwpgsim2d completion b"));
    }

    [Fact]
    public void OptionsAlreadyGivenOnceAreNotOfferedAgainButRepeatableOnesAre()
    {
        var after = Complete("urwpgsim2d run --seed 1 --strategy 0=idle --");
        Assert.DoesNotContain("--seed", after);
        Assert.Contains("--strategy", after);
        Assert.Contains("--item", after);
    }

    [Fact]
    public void FilesAndFoldersCompleteWhereAFileIsTaken()
    {
        string folder = Directory.CreateTempSubdirectory("completion").FullName;
        try
        {
            File.WriteAllText(Path.Combine(folder, "pairs.json"), "[]");
            File.WriteAllText(Path.Combine(folder, "plan.txt"), string.Empty);
            Directory.CreateDirectory(Path.Combine(folder, "proj"));
            string p = Path.Combine(folder, "p");
            string[] all = [p + "airs.json", p + "lan.txt", p + "roj/"];
            Assert.Equal(all, Complete($"urwpgsim2d collide {p}"));
            Assert.Equal(all, Complete($"urwpgsim2d run --trace {p}"));
            Assert.Equal([p + "roj/"], Complete($"urwpgsim2d run --batch 2 --slurm {p}"));
            Assert.Contains("1=" + p + "roj/", Complete($"urwpgsim2d run --strategy 1={p}"));
            Assert.Equal([p + "airs.json"], Complete($"urwpgsim2d render {p}a"));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void TheDirectiveAnswersOneCompletionALineWithExitCodeZero()
    {
        string line = "urwpgsim2d run --it";
        var run = CliRun.Of(string.Empty, $"[suggest:{line.Length}]", line);
        Assert.Equal((0, "--item\n", string.Empty), (run.ExitCode, run.Stdout, run.Stderr));

        var atEnd = CliRun.Of(string.Empty, "[suggest]", "urwpgsim2d view t.jsonl --ht");
        Assert.Equal((0, "--html\n"), (atEnd.ExitCode, atEnd.Stdout));

        var middle = CliRun.Of(string.Empty, "[suggest:18]", "urwpgsim2d run --it --seed 1");
        Assert.Equal("--item\n", middle.Stdout); // the cursor after "--i": what follows it is ignored
    }

    [Theory]
    [InlineData("[suggest:x]")]
    [InlineData("[suggest:99]")]
    [InlineData("[suggest:-1]")]
    public void ABadPositionIsOneLineWithExitCodeTwo(string directive)
    {
        var run = CliRun.Of(string.Empty, directive, "urwpgsim2d run");
        Assert.Equal((2, string.Empty), (run.ExitCode, run.Stdout));
        Assert.Equal($"completion: the request must be [suggest:N] with N a cursor position 0..14 in the line, got \"{directive}\"\n", run.Stderr);
    }

    private static string[] Complete(string line) => ShellCompletion.Complete(CliApp.Default.Root, line, line.Length);
}
