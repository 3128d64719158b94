using System.CommandLine;
using System.CommandLine.Completions;
using System.Text.RegularExpressions;
using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Tests.Cli.Syntax;

/// <summary>
/// Each command's options are declared once, and the parser, <c>--help</c> and shell completion
/// agree with the declarations and with each other. Checked on the program's real behaviour: the
/// options the usage line of <c>COMMAND --help</c> names, the options <c>[suggest]</c> offers after
/// <c>COMMAND --</c>, and the options the command accepts (each given with a sample value is not
/// refused as unknown; an undeclared one is, with exit code 2).
/// </summary>
public sealed partial class OptionDeclarationTests
{
    private const string Undeclared = "--zzqx-undeclared";

    public static TheoryData<string> Commands() => [.. CliApp.DefaultCommands.Select(c => c.Name)];

    [Theory]
    [MemberData(nameof(Commands))]
    public void HelpListsTheDeclaredOptions(string name)
    {
        var help = CliRun.Of(string.Empty, name, "--help");
        Assert.Equal((0, string.Empty), (help.ExitCode, help.Stderr));
        string usage = help.Stdout.Split('\n')[0];
        Assert.StartsWith($"Usage: {CliApp.ProgramName} {name}", usage, StringComparison.Ordinal);
        Assert.Equal(Declared(name), Named(usage));
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void CompletionOffersTheDeclaredOptions(string name)
    {
        string line = $"{CliApp.ProgramName} {name} --";
        var offered = CliRun.Of(string.Empty, "[suggest]", line);
        Assert.Equal(0, offered.ExitCode);
        var options = offered.Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries).Where(o => o != "--help");
        Assert.All(options, o => Assert.StartsWith("--", o, StringComparison.Ordinal));
        Assert.Equal(Declared(name), options.Order(StringComparer.Ordinal));
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void TheCommandAcceptsEveryDeclaredOption(string name)
    {
        Command syntax = CliApp.Default.Root.Subcommands.Single(c => c.Name == name);
        foreach (Option option in syntax.Options.Where(o => o.Name != "--help"))
        {
            string[] given = CliSyntax.TakesValue(option) ? [option.Name, Sample(option)] : [option.Name];

            // The parser takes it as the option, with its value.
            var word = Assert.Single(CliApp.Default.Words(name, given));
            Assert.Same(option, word.Option);
            Assert.Equal(CliSyntax.TakesValue(option) ? given[1] : null, word.Value);

            // The command does not refuse it as unknown; the undeclared option after it stops the command.
            var run = CliRun.Of(string.Empty, [name, .. given, Undeclared]);
            Assert.Equal(2, run.ExitCode);
            Assert.Equal(string.Empty, run.Stdout);
            Assert.DoesNotContain($"unknown option \"{option.Name}\"", run.Stderr, StringComparison.Ordinal);
        }
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void AnUndeclaredOptionIsRefusedByName(string name)
    {
        var run = CliRun.Of(string.Empty, name, Undeclared);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.StartsWith($"{name}: unknown option \"{Undeclared}\"", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
    }

    [Fact]
    public void TheUsageLineIsWrittenFromTheDeclarations()
    {
        // Independent of the renderer: the grouping a reader of the help relies on.
        Assert.Contains("[--item NAME | --scenario FILE | --crowd N] [--minutes 10|5|3|1 | --cycles N]", RunOptions.Usage, StringComparison.Ordinal);
        Assert.Contains("[--strategy TEAM=SPEC|TEAM=remote:PORT]...", RunOptions.Usage, StringComparison.Ordinal);
        Assert.Contains("[--live [--port N] [--host H] [--speed X] [--paused] [--strategies DIR]]", RunOptions.Usage, StringComparison.Ordinal);
        Assert.Contains("(--entrant NAME=SPEC | --entrants-dir DIR)...", TournamentOptions.Usage, StringComparison.Ordinal);
        Assert.Contains("[--shard I/K --results FILE] [--merge FILE...]", TournamentOptions.Usage, StringComparison.Ordinal);
        Assert.Equal("merge [--out FILE [--force]] FILE...", CliApp.DefaultCommands.Single(c => c.Name == "merge").Synopsis);
        Assert.Equal("view TRACE.jsonl --html FILE [--force]", CliApp.DefaultCommands.Single(c => c.Name == "view").Synopsis);
    }

    // The declared long options of the command but --help, in ordinal order.
    private static IEnumerable<string> Declared(string name)
    {
        var names = CliSyntax.LongNames(CliApp.Default.Root.Subcommands.Single(c => c.Name == name)).Where(o => o != "--help").ToList();
        return names.Order(StringComparer.Ordinal);
    }

    // The long options a usage line names, each once, in ordinal order.
    private static IEnumerable<string> Named(string usage) =>
        OptionName().Matches(usage).Select(m => m.Value).Distinct().Order(StringComparer.Ordinal);

    // A value the option's completion offers first, else a number.
    private static string Sample(Option option)
    {
        var offered = option.GetCompletions(CompletionContext.Empty).Select(c => c.Label).FirstOrDefault(l => !l.EndsWith('/') && !l.EndsWith('='));
        return offered ?? "1";
    }

    [GeneratedRegex("(?<![\\w-])--[a-z0-9][a-z0-9-]*")]
    private static partial Regex OptionName();
}
