namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// docs/tournament.md's walkthrough is real: each block marked
/// <c>&lt;!-- output: not run (… TournamentWalkthroughTests: NAME) --&gt;</c> is played in order in a fresh
/// folder standing for <c>tour</c> (and one for <c>cup</c>) (a <c>tournament</c> command in process from the repository root's
/// paths, or <c>cat tour/FILE</c>) and must show exactly its output, wall time aside. With
/// <c>URWPGSIM2D_REGENERATE_DOCS=1</c> the test writes the real outputs into the page instead.
/// </summary>
// Its user entrant plays in strategy hosts at the default 100 ms deadline beside parallel tests: a
// call made late by a busy machine is waited for and paid from the team's time bank, so the results
// are the same however busy the test process is.
public sealed class TournamentWalkthroughTests() : TempFolderTest("urwpg-walkthrough-")
{
    private const string Page = "docs/tournament.md";
    private const string Marker = "TournamentWalkthroughTests: ";

    [Fact]
    public void TheWalkthroughShowsWhatTheCommandsPrintAndWrite()
    {
        string tour = Path.Combine(Folder, "tour");
        var blocks = MarkdownBlock.Read(Page).Where(b => b.Marker?.Contains(Marker, StringComparison.Ordinal) == true).ToList();
        Assert.Equal(["run", "json", "md", "again", "cup"], blocks.Select(b => b.Marker![(b.Marker!.IndexOf(Marker, StringComparison.Ordinal) + Marker.Length)..].TrimEnd(')')));
        var problems = new List<string>();
        var rewritten = new List<(MarkdownBlock Block, string Text)>();
        foreach (var block in blocks)
        {
            string command = block.Text.Split('\n')[0];
            Assert.StartsWith("$ ", command, StringComparison.Ordinal);
            string actual = command.StartsWith("$ cat tour/", StringComparison.Ordinal)
                ? File.ReadAllText(Path.Combine(tour, command["$ cat tour/".Length..])).TrimEnd('\n')
                    .Replace(Repository.PathOf("samples/"), "samples/", StringComparison.Ordinal) // the entrants' code as the command names it
                : Play(command, tour);
            string shown = string.Join('\n', block.Text.Split('\n').Skip(1));
            if (!Transcript.Matches(shown, actual))
            {
                problems.Add($"{block.Where}: `{command}` gives\n{actual}\nbut the page shows\n{shown}");
            }

            rewritten.Add((block, command + "\n" + actual));
        }

        if (Environment.GetEnvironmentVariable("URWPGSIM2D_REGENERATE_DOCS") == "1")
        {
            Rewrite(rewritten);
            return;
        }

        Assert.True(problems.Count == 0, string.Join("\n\n", problems) + "\n(bash scripts/regenerate-docs-outputs.sh writes the real outputs into the page)");
    }

    // "$ urwpgsim2d tournament …" with the folder tour and the repository's relative paths made absolute.
    private static string Play(string command, string tour)
    {
        string[] words = command.Split(' ', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal("urwpgsim2d", words[1]);
        string cup = Path.Combine(Path.GetDirectoryName(tour)!, "cup");
        var args = words.Skip(2).Select(w => w == "tour" ? tour : w == "cup" ? cup : w.Contains("=samples/", StringComparison.Ordinal) ? w[..(w.IndexOf('=', StringComparison.Ordinal) + 1)] + Repository.PathOf(w[(w.IndexOf('=', StringComparison.Ordinal) + 1)..]) : w).ToArray();
        URWPGSim2D.Hosting.CompiledImages.Forget(); // each command is a process of its own: it compiles the sample again
        var run = CliRun.Of(string.Empty, args);
        Assert.True(run.ExitCode == 0, run.Stderr);
        return (run.Stdout + run.Stderr).TrimEnd('\n').Replace(cup, "cup", StringComparison.Ordinal).Replace(tour, "tour", StringComparison.Ordinal)
            .Replace(Repository.PathOf("samples/"), "samples/", StringComparison.Ordinal); // the compile lines name the spec as given
    }

    private static void Rewrite(List<(MarkdownBlock Block, string Text)> replacements)
    {
        string path = Repository.PathOf(Page);
        var lines = File.ReadAllLines(path).ToList();
        foreach (var (block, text) in replacements.OrderByDescending(r => r.Block.Line))
        {
            lines.RemoveRange(block.Line, block.Text.Split('\n').Length);
            lines.InsertRange(block.Line, text.Split('\n'));
        }

        File.WriteAllText(path, string.Join('\n', lines) + "\n");
    }
}
