namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// Typos on the command line: an unknown option or command near a known one is one short line with
/// "did you mean", exit code 2, in every command; item names are matched without regard to case,
/// and an unknown one lists every name with the original's Chinese name.
/// </summary>
public sealed class SuggestionTests
{
    [Theory]
    [InlineData("kitten", "sitting", 3)]
    [InlineData("ab", "ba", 1)]
    [InlineData("", "abc", 3)]
    [InlineData("--Minutes", "--minutes", 0)]
    [InlineData("--strategey", "--strategy", 1)]
    [InlineData("ca", "abc", 3)] // optimal string alignment: no edit of a swapped pair
    public void DistanceIsEditsWithSwapsWithoutRegardToCase(string a, string b, int edits)
    {
        Assert.Equal(edits, Suggestion.Distance(a, b));
        Assert.Equal(edits, Suggestion.Distance(b, a));
    }

    [Fact]
    public void DistanceAgreesWithBruteForceOnShortWords()
    {
        // Every pair of words of up to 3 letters over {a, b}: the fewest edits found by searching
        // all words reachable by 0, 1, 2, ... single edits (insert, delete, substitute, swap) —
        // for words this short, no edit string re-edits a swapped pair, so the search is exact.
        string[] words = [.. Words(3)];
        foreach (string a in words)
        {
            var reach = new System.Collections.Generic.HashSet<string> { a };
            var steps = new System.Collections.Generic.Dictionary<string, int> { [a] = 0 };
            for (int n = 1; n <= 6; n++)
            {
                foreach (string w in reach.ToList())
                {
                    foreach (string e in Edits(w).Where(e => e.Length <= 5 && steps.TryAdd(e, n)))
                    {
                        reach.Add(e);
                    }
                }
            }

            foreach (string b in words)
            {
                Assert.Equal(steps[b], Suggestion.Distance(a, b));
            }
        }
    }

    [Theory]
    [InlineData("unknown option \"--minute\"; did you mean --minutes?", "run", "--minute", "1")]
    [InlineData("unknown option \"--minute\"; did you mean --minutes?", "run", "--minute")]
    [InlineData("unknown option \"--strategey\"; did you mean --strategy?", "run", "--strategey", "0=idle")]
    [InlineData("unknown option \"--sbatch-args\"; did you mean --sbatch-arg?", "run", "--sbatch-args", "--qos=x")]
    [InlineData("unknown option \"--entrnt\"; did you mean --entrant?", "tournament", "--entrnt", "a=idle")]
    [InlineData("unknown option \"--outt\"; did you mean --out?", "merge", "--outt", "x")]
    [InlineData("unknown option \"--forse\"; did you mean --force?", "view", "--forse")]
    [InlineData("unknown option \"--tokn\"; did you mean --token?", "connect", "127.0.0.1:1", "idle", "--tokn", "x")]
    [InlineData("unknown option \"--hlep\"; did you mean --help?", "collide", "--hlep")]
    [InlineData("unknown option \"--hepl\"; did you mean --help?", "shapes", "--hepl")]
    [InlineData("unknown option \"--hlep\"; did you mean --help?", "query", "--hlep")]
    [InlineData("unknown option \"--sgv\"; did you mean --svg?", "render", "a.json", "--sgv", "x.svg")]
    [InlineData("unknown option \"--hlep\"; did you mean --help?", "host", "--hlep")]
    [InlineData("unknown option \"--list\"; did you mean --list-items?", "run", "--list")]
    public void ATypoOfAnOptionIsOneLineWithTheNearestOptionInEveryCommand(string message, params string[] args)
    {
        var run = CliRun.Of(string.Empty, args);
        Assert.Equal((2, string.Empty, $"{args[0]}: {message}\n"), (run.ExitCode, run.Stdout, run.Stderr));
    }

    [Fact]
    public void ATypoOfACommandNamesTheCommandAndAFarOneKeepsTheUsage()
    {
        Assert.Equal((2, "unknown command \"rn\"; did you mean run?\n"), Failure("rn"));
        Assert.Equal((2, "unknown command \"tournement\"; did you mean tournament?\n"), Failure("tournement"));
        var far = CliRun.Of(string.Empty, "run", "--fast", "1");
        Assert.StartsWith("run: unknown option \"--fast\". Usage: urwpgsim2d run [", far.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public void EveryOptionAUsageNamesIsKnownToItsParser()
    {
        foreach (string option in RunOptions.KnownOptions)
        {
            var run = CliRun.Of(string.Empty, "run", option, "x", "--list-items");
            Assert.DoesNotContain("unknown option", run.Stderr, StringComparison.Ordinal);
        }

        foreach (string option in TournamentOptions.KnownOptions)
        {
            var run = CliRun.Of(string.Empty, "tournament", option, "x");
            Assert.DoesNotContain("unknown option", run.Stderr, StringComparison.Ordinal);
        }

        Assert.Contains("--sbatch-arg", RunOptions.KnownOptions);
        Assert.Contains("--remote-token", RunOptions.KnownOptions);
        Assert.Contains("--merge", TournamentOptions.KnownOptions);
    }

    [Theory]
    [InlineData("BALL-GRAB", "item: ball-grab (抢球博弈)")]
    [InlineData("Polo-1v1", "item: polo-1v1 (水球1VS1)")]
    [InlineData("水球1vs1", "item: polo-1v1 (水球1VS1)")]
    [InlineData("抢球博弈", "item: ball-grab (抢球博弈)")]
    public void ItemNamesAreMatchedWithoutRegardToCase(string name, string itemLine)
    {
        var run = CliRun.Of(string.Empty, "run", "--item", name, "--cycles", "2");
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.StartsWith(itemLine + ",", run.Stdout.Split('\n')[1], StringComparison.Ordinal);
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--item", "Default", "--cycles", "2").ExitCode);
    }

    [Theory]
    [InlineData("水球1v1", "; did you mean polo-1v1?")]
    [InlineData("snoker", "; did you mean snooker?")]
    [InlineData("football", "")]
    public void AnUnknownItemListsEveryNameWithItsChineseNameAndTheNearestItem(string name, string hint)
    {
        foreach (string command in new[] { "run", "tournament" })
        {
            var run = CliRun.Of(string.Empty, command, "--item", name, "--entrant", "a=idle");
            Assert.Equal(2, run.ExitCode);
            string line = Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
            Assert.StartsWith($"{command}: --item must be one of {(command == "run" ? "default, " : string.Empty)}ball-grab (抢球博弈), ", line, StringComparison.Ordinal);
            Assert.All(ItemRegistry.All, i => Assert.Contains($"{i.Slug} ({i.ChineseName})", line, StringComparison.Ordinal));
            Assert.EndsWith($", got \"{name}\"{hint}", line, StringComparison.Ordinal);
        }
    }

    private static (int, string) Failure(params string[] args)
    {
        var run = CliRun.Of(string.Empty, args);
        return (run.ExitCode, run.Stderr);
    }

    private static System.Collections.Generic.IEnumerable<string> Words(int length)
    {
        yield return string.Empty;
        for (int n = 1; n <= length; n++)
        {
            for (int bits = 0; bits < 1 << n; bits++)
            {
                yield return new string([.. Enumerable.Range(0, n).Select(i => (bits >> i & 1) == 0 ? 'a' : 'b')]);
            }
        }
    }

    private static System.Collections.Generic.IEnumerable<string> Edits(string w)
    {
        for (int i = 0; i <= w.Length; i++)
        {
            yield return w.Insert(i, "a");
            yield return w.Insert(i, "b");
        }

        for (int i = 0; i < w.Length; i++)
        {
            yield return w.Remove(i, 1);
            yield return w.Remove(i, 1).Insert(i, w[i] == 'a' ? "b" : "a");
            if (i + 1 < w.Length)
            {
                yield return w[..i] + w[i + 1] + w[i] + w[(i + 2)..];
            }
        }
    }
}
