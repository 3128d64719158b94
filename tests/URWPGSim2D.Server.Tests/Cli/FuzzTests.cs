namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// Fuzzing of every JSON reader of the command line, in process: thousands of mutations
/// (<see cref="JsonMutator"/>) of a valid input per reader, each run as a user would. Every run
/// must exit 0 or 2; on 2 stderr is exactly one line, stdout is empty and no output file exists.
/// A failure names the reader, seed and case index, and keeps the input to replay.
/// </summary>
public sealed class FuzzTests() : TempFolderTest("urwpg-fuzz-")
{
    private const int Seed = 20261201;

    /// <inheritdoc/>

    [Fact]
    public void Collide() => Fuzz("collide", Read("examples/pairs.json"), 2000, (input, _) => ["collide", input]);

    [Fact]
    public void Shapes() => Fuzz("shapes", Read("examples/shapes.json"), 2000, (input, _) => ["shapes", input]);

    [Fact]
    public void Render() => Fuzz("render", Read("docs/figures/fish-ball-contact.json"), 1500, (input, output) => ["render", input, "--svg", Path.Combine(output, "f.svg")]);

    [Fact]
    public void RenderPairs() => Fuzz("render-pairs", Read("examples/pairs.json"), 500, (input, output) => ["render", input, "--svg", Path.Combine(output, "f.svg")]);

    [Fact]
    public void RunScenario() =>
        Fuzz("run --scenario", Read("examples/scenario.json"), 1500, (input, output) => ["run", "--scenario", input, "--cycles", "0", "--trace", Path.Combine(output, "t.jsonl")]);

    [Fact]
    public void Merge()
    {
        string results = Path.Combine(Folder, "seed.jsonl");
        var batch = CliRun.Of(string.Empty, "run", "--batch", "2", "--cycles", "2", "--threads", "1", "--results", results);
        Assert.Equal(0, batch.ExitCode);
        Fuzz("merge", File.ReadAllBytes(results), 2000, (input, output) => ["merge", "--out", Path.Combine(output, "all.jsonl"), input]);
    }

    private static byte[] Read(string relative) => File.ReadAllBytes(Repository.PathOf(relative));

    private void Fuzz(string reader, byte[] valid, int cases, Func<string, string, string[]> arguments)
    {
        string input = Path.Combine(Folder, "input.json");
        string output = Path.Combine(Folder, "out");
        Directory.CreateDirectory(output);

        // The unmutated input must succeed, or the fuzzing would test nothing but the error path.
        File.WriteAllBytes(input, valid);
        var original = CliRun.Of(string.Empty, arguments(input, output));
        Assert.True(original.ExitCode == 0, $"{reader}: the valid seed input fails: {original.Stderr}");
        Directory.Delete(output, recursive: true);
        Directory.CreateDirectory(output);

        var mutator = new JsonMutator(Seed + reader.Sum(c => c));
        int rejected = 0;
        var failures = new List<string>();
        for (int index = 0; index < cases && failures.Count < 5; index++)
        {
            byte[] mutated = mutator.Mutate(valid);
            File.WriteAllBytes(input, mutated);
            CliRun run = CliRun.Of(string.Empty, arguments(input, output));
            string? problem = run.ExitCode switch
            {
                0 => null,
                2 when run.Stdout.Length > 0 => "exit 2 with output on stdout",
                2 when run.Stderr.Length == 0 || !run.Stderr.EndsWith('\n') || run.Stderr.IndexOf('\n') != run.Stderr.Length - 1 => $"exit 2 without exactly one stderr line: {run.Stderr}",
                2 when Directory.EnumerateFileSystemEntries(output).Any() => $"exit 2 but wrote {string.Join(", ", Directory.EnumerateFileSystemEntries(output).Select(Path.GetFileName))}",
                2 => null,
                _ => $"exit {run.ExitCode}: {run.Stderr.TrimEnd()}",
            };

            if (run.ExitCode == 2)
            {
                rejected++;
            }

            if (problem is not null)
            {
                string keep = Path.Combine(Path.GetTempPath(), $"urwpg-fuzz-{reader.Replace(' ', '-')}-{index}.json");
                File.WriteAllBytes(keep, mutated);
                failures.Add($"{reader}, seed {Seed + reader.Sum(c => c)}, case {index}: {problem} (input kept in {keep})");
            }

            foreach (string entry in Directory.EnumerateFileSystemEntries(output))
            {
                File.Delete(entry);
            }
        }

        Assert.True(failures.Count == 0, string.Join('\n', failures));

        // The mutations must reach the error paths, and not only them.
        Assert.True(rejected > cases / 4 && rejected < cases, $"{reader}: {rejected} of {cases} mutated inputs rejected");
    }
}
