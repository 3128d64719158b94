using System.Text.RegularExpressions;
using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Tests.Cli.Syntax;

/// <summary>
/// How System.CommandLine's parse becomes the words a command checks: a value option takes the
/// next word whatever it looks like, words keep their order, and each command's declared options
/// are exactly those its usage names.
/// </summary>
public sealed partial class CommandLineWordsTests
{
    [Fact]
    public void AValueOptionTakesTheNextWordWhateverItLooksLike()
    {
        var words = CliApp.Default.Words("run", ["--sbatch-arg", "--mem=2G", "--trace", "--svg", "x", "--seed", "-1"]);
        Assert.Equal(
            [("--sbatch-arg", "--mem=2G"), ("--trace", "--svg"), ("x", null), ("--seed", "-1")],
            words.Select(w => (w.Text, w.Value)).ToArray());
        Assert.Equal([true, true, false, true], words.Select(w => w.IsOption).ToArray());
    }

    [Fact]
    public void WordsKeepTheirOrderAndRepeatsStaySeparate()
    {
        var words = CliApp.Default.Words("run", ["--seed", "1", "stray", "--seed", "2", "--live", "-h", "--strategey", "0=idle"]);
        Assert.Equal(
            ["--seed=1", "stray", "--seed=2", "--live", "--help", "--strategey", "0=idle"],
            words.Select(w => w.Value is null ? w.Name : $"{w.Name}={w.Value}").ToArray());
        Assert.Equal("-h", words[4].Text);
        Assert.False(words[5].IsOption); // an unknown option is the command's to report
    }

    [Fact]
    public void AMissingValueIsAnOptionWithoutOne()
    {
        var last = CliApp.Default.Words("run", ["--cycles"]).Single();
        Assert.True(last.LacksValue);
        Assert.False(CliApp.Default.Words("run", ["--live"]).Single().LacksValue);
    }

    [Fact]
    public void TheEqualsFormIsTheSameAsTwoWords()
    {
        var words = CliRun.Of(string.Empty, "run", "--seed", "7", "--cycles", "3");
        var equals = CliRun.Of(string.Empty, "run", "--seed=7", "--cycles=3");
        Assert.Equal((0, string.Empty), (equals.ExitCode, equals.Stderr));
        Assert.EndsWith(", seed 7", equals.Stdout.Split('\n')[0], StringComparison.Ordinal);
        Assert.Equal(words.Stdout.Split('\n')[1..], equals.Stdout.Split('\n')[1..]); // the first line has the wall time
    }

    [Fact]
    public void ResponseFilesAreOrdinaryArguments()
    {
        var run = CliRun.Of(string.Empty, "collide", "@pairs.json");
        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith("@pairs.json: ", run.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public void EveryCommandDeclaresExactlyTheOptionsItsUsageNames()
    {
        foreach (var command in CliApp.DefaultCommands)
        {
            string usage = command.Name switch
            {
                "run" => RunOptions.Usage,
                "tournament" => TournamentOptions.Usage,
                _ => command.Synopsis,
            };
            var named = OptionNames().Matches(usage).Select(m => m.Value).Append("--help").Distinct().Order(StringComparer.Ordinal);
            Assert.Equal(named, CliSyntax.LongNames(command.Syntax).Order(StringComparer.Ordinal));
            Assert.Same(command.Syntax, CliApp.Default.Root.Subcommands.Single(c => c.Name == command.Name));
        }
    }

    [GeneratedRegex("--[a-z0-9][a-z0-9-]*")]
    private static partial Regex OptionNames();
}
