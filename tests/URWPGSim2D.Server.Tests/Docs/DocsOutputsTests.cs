namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// Every command output the docs show is real: each transcript block (first line <c>$ …</c>,
/// <see cref="Transcript"/>) of README.md and docs/ is run with the server built next to the tests,
/// from the repository root, and must print exactly what the block shows, timing figures aside
/// (<see cref="Transcript.Mask"/>); a shown <c> ... </c> stands for any text (a long line cut short). A block checked by another CI script says so on the line before
/// it (<c>&lt;!-- .ci/slurm checks: … --&gt;</c>); a command that does not end by itself (a server) is marked
/// <c>&lt;!-- output: not run (WHY) --&gt;</c>. With <c>URWPGSIM2D_REGENERATE_DOCS=1</c> the test
/// writes the real outputs into the docs instead (scripts/regenerate-docs-outputs.sh).
/// </summary>
public sealed class DocsOutputsTests
{
    private static readonly bool Regenerate = Environment.GetEnvironmentVariable("URWPGSIM2D_REGENERATE_DOCS") == "1";

    /// <summary>The Markdown files, one test case each.</summary>
    public static TheoryData<string> Files() => [.. Repository.MarkdownFiles()];

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryShownOutputIsTheCommandsOutput(string file)
    {
        var problems = new List<string>();
        var replacements = new List<(MarkdownBlock Block, string Text)>();
        foreach (var block in MarkdownBlock.Read(file).Where(RunsForReal))
        {

            Transcript transcript;
            try
            {
                transcript = Transcript.Parse(block.Text);
            }
            catch (FormatException e)
            {
                problems.Add($"{block.Where}: {e.Message}");
                continue;
            }

            var actualBlock = new List<string>();
            int lastCode = 0;
            foreach (var step in transcript.Steps)
            {
                actualBlock.AddRange(("$ " + step.Command).Split('\n'));
                string actual;
                if (step.Arguments is null)
                {
                    actual = lastCode.ToString(System.Globalization.CultureInfo.InvariantCulture);
                }
                else
                {
                    var (code, stdout, stderr) = RunServer(step.Stdin, step.Arguments);
                    lastCode = code;
                    actual = (stdout + stderr).TrimEnd('\n');
                }

                string shown = string.Join('\n', step.Expected);
                bool same = Transcript.Matches(shown, actual);
                actualBlock.AddRange(same ? step.Expected : actual.Length == 0 ? [] : actual.Split('\n'));
                if (!same)
                {
                    problems.Add($"{block.Where}: `{step.Command}` prints\n{actual}\nbut the docs show\n{shown}");
                }
            }

            replacements.Add((block, string.Join('\n', actualBlock)));
        }

        if (Regenerate)
        {
            Rewrite(file, replacements);
            return;
        }

        Assert.True(problems.Count == 0, string.Join("\n\n", problems) + "\n(bash scripts/regenerate-docs-outputs.sh writes the real outputs into the docs)");
    }

    /// <summary>
    /// Whether this test runs a block: a transcript (first line <c>$ …</c>) unless the line before it
    /// says that a CI script checks it or (saying why) that it is not run, as for a command that does
    /// not end by itself.
    /// </summary>
    internal static bool RunsForReal(MarkdownBlock block) =>
        block.Text.StartsWith("$ ", StringComparison.Ordinal)
        && !(block.Marker is { } marker && (marker.StartsWith(".ci/", StringComparison.Ordinal) || marker.StartsWith("output: not run", StringComparison.Ordinal)));

    /// <summary>
    /// The merge log that docs/batch.md shows for the Slurm recipe (checked for real by .ci/slurm,
    /// which needs a cluster) is what <c>merge</c> prints for the same batch played here, so a change
    /// of the motion that alters it fails the suite and the regeneration rewrites it too.
    /// </summary>
    [Fact]
    public void TheSlurmMergeLogIsTheMergeOfTheSameBatchPlayedHere()
    {
        const string file = "docs/batch.md";
        MarkdownBlock block = MarkdownBlock.Read(file).Single(b => b.Marker == ".ci/slurm checks: merge log");
        string[] shown = block.Text.Split('\n');
        Assert.StartsWith("$ cat ", shown[0], StringComparison.Ordinal);

        string results = Path.Combine(Path.GetTempPath(), $"urwpg-docs-merge-{Environment.ProcessId}.jsonl");
        string merged = Path.Combine(Path.GetTempPath(), $"urwpg-docs-merged-{Environment.ProcessId}.jsonl");
        try
        {
            var (played, _, playErrors) = RunServer("", ["run", "--batch", "8", "--cycles", "200", "--results", results]);
            Assert.True(played == 0, playErrors);

            // The merge job runs merge --out DIR/results.jsonl: its log ends with the line for that file.
            var (code, stdout, mergeErrors) = RunServer("", ["merge", "--out", merged, results]);
            Assert.True(code == 0, mergeErrors);
            string actual = stdout.TrimEnd('\n').Replace(merged, "/scratch/urwpg/batch-8/results.jsonl", StringComparison.Ordinal);
            if (Regenerate)
            {
                Rewrite(file, [(block, shown[0] + "\n" + actual)]);
                return;
            }

            Assert.Equal(string.Join('\n', shown.Skip(1)), actual);
        }
        finally
        {
            File.Delete(results);
            File.Delete(merged);
        }
    }

    [Fact]
    public void TheMaskHidesOnlyTimingFigures()
    {
        Assert.Equal(
            "match: 3000 cycles, 300.0 s simulated in <T> wall time (<T>x real time, <T> us per cycle)",
            Transcript.Mask("match: 3000 cycles, 300.0 s simulated in 1556.6 ms wall time (193x real time, 518.88 us per cycle)"));
        Assert.Equal(
            "wall time: <T> s on <T> threads, <T> matches/s, <T>x real time",
            Transcript.Mask("wall time: 0.447 s on 2 threads, 8.94 matches/s, 2682x real time"));
        Assert.NotEqual(Transcript.Mask("match: 3000 cycles, 300.0 s simulated"), Transcript.Mask("match: 3001 cycles, 300.0 s simulated"));
        const string Bank = "strategy time: 100 ms of CPU time a call, a time bank of 18.0 s a team for late calls:";
        Assert.Equal(Transcript.Mask(Bank + " none drawn\nnext"), Transcript.Mask(Bank + "\n  team 0 (toward the ball [SdkStrategy.cs]): 2 late calls, 0.153 s drawn, slowest call 230 ms\nnext"));
        Assert.Equal(Transcript.Mask(Bank + " none drawn"), Transcript.Mask(Bank + "\n  team 0 (a): 1 late call, 0.050 s drawn, slowest call 150 ms\n  team 1 (b): 3 late calls, 0.612 s drawn, slowest call 305 ms"));
        Assert.NotEqual(Transcript.Mask(Bank + " none drawn\n"), Transcript.Mask(Bank + "\n  team 0 (a): 40 late calls, 18.000 s drawn, bank spent, slowest call 900 ms\n"));
        Assert.Equal("goals: team 0 (chase-ball) 1, team 1 (chase-ball) 0", Transcript.Mask("goals: team 0 (chase-ball) 1, team 1 (chase-ball) 0"));
        Assert.True(Transcript.Matches("[1, ... ,9]", "[1,2,3,4,5,6,7,8,9]"));
        Assert.False(Transcript.Matches("[1, ... ,9]", "[1,2,3,4,5,6,7,8,0]"));
        Assert.False(Transcript.Matches("[1,2]", "[1,2,3]"));
    }

    [Fact]
    public void TheTranscriptReaderUnderstandsTheDocsCommands()
    {
        var t = Transcript.Parse("$ echo '[1,\n  2]' | urwpgsim2d collide -\nout\n$ echo $?\n0\n$ dotnet run -c Release --project src/URWPGSim2D.Server -- run --batch 4\na\nb");

        Assert.Equal(3, t.Steps.Count);
        Assert.Equal(["collide", "-"], t.Steps[0].Arguments!);
        Assert.Equal("[1,\n  2]\n", t.Steps[0].Stdin);
        Assert.Equal(["out"], t.Steps[0].Expected);
        Assert.Null(t.Steps[1].Arguments);
        Assert.Equal(["run", "--batch", "4"], t.Steps[2].Arguments!);
        Assert.Equal(["a", "b"], t.Steps[2].Expected);
        Assert.Throws<FormatException>(() => Transcript.Parse("$ cat x.json"));
        Assert.Throws<FormatException>(() => Transcript.Parse("$ urwpgsim2d collide x.json > y"));
        Assert.Throws<FormatException>(() => Transcript.Parse("$ URWPGSim2D.Server run --cycles 1")); // the program is urwpgsim2d
    }

    private static void Rewrite(string file, List<(MarkdownBlock Block, string Text)> replacements)
    {
        string path = Repository.PathOf(file);
        var lines = File.ReadAllLines(path).ToList();
        foreach (var (block, text) in replacements.OrderByDescending(r => r.Block.Line))
        {
            int first = block.Line; // the line after the fence (0-based index of the block's first line)
            int count = block.Text.Split('\n').Length;
            lines.RemoveRange(first, count);
            lines.InsertRange(first, text.Split('\n'));
        }

        File.WriteAllText(path, string.Join('\n', lines) + "\n");
    }

    /// <summary>Runs the server built next to the tests from the repository root, with standard input <paramref name="stdin"/>.</summary>
    internal static (int Code, string Stdout, string Stderr) RunServer(string stdin, string[] args)
    {
        string server = Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll");
        var start = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardInput = true,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            WorkingDirectory = Repository.Root,
        };
        start.ArgumentList.Add(server);
        foreach (string arg in args)
        {
            start.ArgumentList.Add(arg);
        }

        using var process = Process.Start(start) ?? throw new InvalidOperationException("the server did not start");
        var stderr = process.StandardError.ReadToEndAsync();
        var stdout = process.StandardOutput.ReadToEndAsync();
        process.StandardInput.Write(stdin);
        process.StandardInput.Close();
        if (!process.WaitForExit(300_000))
        {
            process.Kill();
            throw new TimeoutException($"the server did not exit within 5 minutes: {string.Join(' ', args)}");
        }

        return (process.ExitCode, stdout.Result, stderr.Result);
    }
}
