using System.Collections.Concurrent;
using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// Every command of the server that a page shows exists (README.md, the Chinese pages, docs/, the
/// package READMEs; a transcript's commands are run for real by <see cref="DocsOutputsTests"/>): the command
/// answers <c>COMMAND --help</c>, every option shown is in that help, every <c>--item</c> shown is an
/// item of <c>run --list-items</c> (its English or Chinese name), and the commands that only print
/// (<c>--help</c>, <c>--list-items</c>) are run and must succeed. The real program is asked, so a
/// page that shows an option the program does not have fails here.
/// </summary>
public sealed partial class DocsCommandsTests
{
    private static readonly ConcurrentDictionary<string, (int Code, string Text)> Help = new(StringComparer.Ordinal);
    private static readonly Lazy<string[]> Items = new(() =>
    {
        var (code, stdout, stderr) = DocsOutputsTests.RunServer("", ["run", "--list-items"]);
        Assert.True(code == 0, stderr);
        return [.. stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries).SelectMany(l => l.Split(' ', StringSplitOptions.RemoveEmptyEntries).Take(2))];
    });

    /// <summary>Every page, one test case each.</summary>
    public static TheoryData<string> Pages() => [.. Repository.MarkdownFiles()];

    [Theory]
    [MemberData(nameof(Pages))]
    public void EveryCommandShownExists(string file)
    {
        var commands = ShownCommand.In(file).ToList();
        var problems = commands.SelectMany(Check).ToList();
        Assert.True(problems.Count == 0, string.Join('\n', problems));
    }

    [Fact]
    public void EveryChinesePageShowsTheServersCommands()
    {
        // The pages are there, and they show how to play an item, a strategy and a page.
        var shown = Repository.TranslatedPages().SelectMany(ShownCommand.In).ToList();
        Assert.Contains(shown, c => c.Command == "run" && c.ValueOf("--item") is not null);
        Assert.Contains(shown, c => c.Command == "run" && c.Options().Contains("--strategy"));
        Assert.Contains(shown, c => c.Command == "run" && c.Options().Contains("--html"));
        Assert.Contains(shown, c => c.Command == "run" && c.Options().Contains("--live"));
    }

    [Theory]
    [InlineData("urwpgsim2d run --minute 1", "--minute")]
    [InlineData("urwpgsim2d run --item polo-1v1 --strategey 0=demo", "--strategey")]
    [InlineData("$ urwpgsim2d tournament --item ball-grab --entrants a=demo --out t", "--entrants")]
    [InlineData("dotnet run -c Release --project src/URWPGSim2D.Server -- view t.jsonl --htm m.html", "--htm")]
    [InlineData("urwpgsim2d play --item ball-grab", "play")]
    [InlineData("urwpgsim2d run --item 水球", "水球")]
    [InlineData("urwpgsim2d run --item ballgrab   # ball-grab", "ballgrab")]
    public void TheCheckFindsAnUnknownCommandOptionOrItem(string line, string named)
    {
        var problems = Check(Shown(line)).ToList();
        Assert.Single(problems);
        Assert.Contains($"\"{named}\"", problems[0], StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("urwpgsim2d run --item 抢球博弈 --minutes 1 --strategy 0=MyTeam/bin/x.dll#Ns.Type --html match.html")]
    [InlineData("urwpgsim2d run --item polo-1v1 --strategy 1=remote:7000  # team 1 waits")]
    [InlineData("$ urwpgsim2d run --list-items")]
    [InlineData("dotnet run -c Release --project src/URWPGSim2D.Server")]
    [InlineData("urwpgsim2d merge --out out/all.jsonl out/shard-*.jsonl")]
    [InlineData("urwpgsim2d tournament --help")]
    public void TheCheckPassesTheProgramsOwnCommands(string line) => Assert.Empty(Check(Shown(line)));

    [Theory]
    [InlineData("dotnet pack src/URWPGSim2D.Server -c Release -o feed")]
    [InlineData("dotnet run -c Release --project benchmarks/URWPGSim2D.Collision.Benchmarks -- --filter '*'")]
    [InlineData("PYTHONPATH=clients/python python3 -m urwpgsim2d.examples.chase_ball 127.0.0.1:7000")]
    public void OtherLinesAreNotCommandsOfTheServer(string line) => Assert.Null(ShownCommand.Parse(line));

    private static ShownCommand Shown(string line) =>
        ShownCommand.Of("line", line) ?? throw new ArgumentException($"not a command of the server: {line}", nameof(line));

    /// <summary>What is wrong with a shown command, one line each (none: it exists as shown).</summary>
    private static IEnumerable<string> Check(ShownCommand shown)
    {
        var (code, help) = Help.GetOrAdd(shown.Command, c =>
        {
            var (exit, stdout, stderr) = DocsOutputsTests.RunServer("", [c, "--help"]);
            return (exit, stdout + stderr);
        });
        if (code != 0)
        {
            yield return $"{shown.Where}: the server has no command \"{shown.Command}\": {shown.Line}";
            yield break;
        }

        foreach (string option in shown.Options().Distinct(StringComparer.Ordinal).Where(o => o is not ("--help" or "-h")))
        {
            if (!Regex.IsMatch(help, $@"(?<![\w-]){Regex.Escape(option)}(?![\w-])", RegexOptions.CultureInvariant))
            {
                yield return $"{shown.Where}: \"{shown.Command} --help\" lists no option \"{option}\": {shown.Line}";
            }
        }

        if (shown.Command == "run" && shown.ValueOf("--item") is { } item && !Items.Value.Contains(item, StringComparer.OrdinalIgnoreCase))
        {
            yield return $"{shown.Where}: \"run --list-items\" lists no item \"{item}\": {shown.Line}";
        }

        // The commands that only print are run as shown.
        if (shown.Options().Any(o => o is "--help" or "-h" or "--list-items"))
        {
            var (exit, _, stderr) = DocsOutputsTests.RunServer("", [shown.Command, .. shown.Arguments]);
            if (exit != 0)
            {
                yield return $"{shown.Where}: exits with code {exit}: {stderr.Trim()}: {shown.Line}";
            }
        }
    }
}
