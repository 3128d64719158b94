namespace URWPGSim2D.Server.Tests.Batch;

/// <summary>
/// <c>run --batch</c>: the results depend only on the batch, never on the thread count or on how
/// the batch is sharded; <c>merge</c> of all shards gives the very file one run writes.
/// </summary>
public sealed class BatchRunTests() : TempFolderTest("urwpg-batch-")
{
    [Fact]
    public void ResultsAreTheSameOnOneThreadAndOnSeveral()
    {
        var one = Batch("one", "--threads", "1");
        var three = Batch("three", "--threads", "3");
        Assert.Equal(File.ReadAllBytes(one.File), File.ReadAllBytes(three.File));
        Assert.Equal(WithoutWallTime(one.Run.Stdout), WithoutWallTime(three.Run.Stdout));
        string[] lines = one.Run.Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(5 + 8, lines.Length);
        Assert.Equal($"wrote {one.File} (the results of 5 matches)", lines[12]);
        for (int j = 0; j < 5; j++)
        {
            Assert.Matches($@"^match {j} \(seed {7 + j}\): score [0-9]+-[0-9]+, (team [01] won by|no winner:) ", lines[j]);
        }

        Assert.Equal("batch: 5 matches, seeds 7 to 11, 40 cycles each, scene item ball-grab", lines[5]);
        Assert.Matches(@"^goals team 0 \(ball-grab demo\): mean [0-9.]+, sd [0-9.]+, min [0-9]+, max [0-9]+, total [0-9]+$", lines[6]);
        Assert.Matches(@"^outcomes: team 0 won [0-9]+, team 1 won [0-9]+, drawn [0-9]+$", lines[8]);
        Assert.Matches(@"^wall time: [0-9.]+ s on 1 threads, [0-9.]+ matches/s, [0-9]+x real time$", lines[11]);
        Assert.Equal(6, File.ReadAllLines(one.File).Length);
    }

    [Fact]
    public void TheSeedsDifferSoTheMatchesDiffer()
    {
        var batch = Batch("seeds", "--threads", "2");
        string[] matches = File.ReadAllLines(batch.File).Skip(1).Select(l => l[l.IndexOf(",\"cycles\"", StringComparison.Ordinal)..]).ToArray();
        Assert.True(matches.Distinct().Count() >= 4, string.Join("\n", matches));
    }

    [Fact]
    public void MergingEveryShardGivesTheFileOfOneRun()
    {
        var whole = Batch("whole");
        string[] shards = new string[3];
        for (int i = 0; i < 3; i++)
        {
            shards[i] = Batch($"shard{i}", "--shard", $"{i}/3", "--threads", "1").File;
        }

        string merged = Path.Combine(Folder, "merged.jsonl");
        var merge = CliRun.Of(string.Empty, ["merge", "--out", merged, shards[2], shards[0], shards[1]]);
        Assert.Equal(0, merge.ExitCode);
        Assert.Equal(File.ReadAllBytes(whole.File), File.ReadAllBytes(merged));
        Assert.Equal(WithoutWallTime(whole.Run.Stdout).Split('\n').Skip(5).ToArray(), WithoutWallTime(merge.Stdout).Split('\n'));

        // Shard 1 of 3 holds matches 1 and 4.
        string[] shardLines = File.ReadAllLines(shards[1]);
        Assert.Contains("\"shard\":1,\"shards\":3", shardLines[0], StringComparison.Ordinal);
        Assert.Equal(new[] { 1, 4 }, shardLines.Skip(1).Select(l => int.Parse(l.Split("\"index\":")[1].Split(',')[0], System.Globalization.CultureInfo.InvariantCulture)));
    }

    [Fact]
    public void MergeRefusesIncompleteOrForeignShards()
    {
        string s0 = Batch("a0", "--shard", "0/2").File;
        string s1 = Batch("a1", "--shard", "1/2").File;
        string other = Batch("b1", seed: 8, "--shard", "1/2").File;
        string bad = Path.Combine(Folder, "bad.jsonl");
        File.WriteAllText(bad, File.ReadAllLines(s1)[0] + "\n{\"kind\":\"match\",\"index\":1}\n");

        AssertError(CliRun.Of(string.Empty, "merge", s0), "missing shard 1 of 2 (give every shard's result file)");
        AssertError(CliRun.Of(string.Empty, "merge", s0, s0), $"{s0}: shard 0/2 is also in {s0}");
        AssertError(CliRun.Of(string.Empty, "merge", s0, other), $"{other}: belongs to another batch than {s0} (first seed 7 vs 8)");
        AssertError(CliRun.Of(string.Empty, "merge", s0, bad), $"{bad}:2: missing field \"seed\"");
        AssertError(CliRun.Of(string.Empty, "merge", Path.Combine(Folder, "none.jsonl")), "cannot read the result file");
        Assert.Equal(0, CliRun.Of(string.Empty, "merge", s1, s0).ExitCode);
    }

    [Fact]
    public void TheResultsCarryEachFaultyTeamsFaultsAndMergeKeepsThem()
    {
        // The test strategy throws on its calls 5-9 and answers no decisions on calls 10-14; in
        // 15 cycles it never hangs, so the counts do not depend on timing.
        string faulty = "0=" + Hosting.OriginalStrategyTests.Folder("Faulty");
        var whole = Batch("faulty", 7, 15, "--strategy", faulty);
        const string entry = "\"strategyFaults\":10,\"faults\":[{\"team\":0,\"strategy\":\"Faulty\",\"exceptions\":5,\"timeouts\":0,\"badAnswers\":5,\"first\":\"cycle 5: InvalidOperationException: faulty on purpose\"}]";
        string[] lines = File.ReadAllLines(whole.File);
        Assert.Equal(6, lines.Length);
        Assert.All(lines.Skip(1), l => Assert.Contains(entry, l, StringComparison.Ordinal));

        // A faultless team has no entry, and a match without faults no "faults" field at all.
        var clean = Batch("clean", 7, 15);
        Assert.All(File.ReadAllLines(clean.File).Skip(1), l => Assert.DoesNotContain("\"faults\"", l, StringComparison.Ordinal));

        // Merging the shards writes the entries back byte for byte.
        string s0 = Batch("f0", 7, 15, "--strategy", faulty, "--shard", "0/2").File;
        string s1 = Batch("f1", 7, 15, "--strategy", faulty, "--shard", "1/2").File;
        string merged = Path.Combine(Folder, "faulty-merged.jsonl");
        Assert.Equal(0, CliRun.Of(string.Empty, "merge", "--out", merged, s1, s0).ExitCode);
        Assert.Equal(File.ReadAllBytes(whole.File), File.ReadAllBytes(merged));

        // Entries that do not add up to strategyFaults, or name no fault, are refused.
        string[] shard1 = File.ReadAllLines(s1);
        string wrong = Path.Combine(Folder, "wrong.jsonl");
        File.WriteAllLines(wrong, [shard1[0], shard1[1].Replace("\"exceptions\":5", "\"exceptions\":4", StringComparison.Ordinal), .. shard1.Skip(2)]);
        AssertError(CliRun.Of(string.Empty, "merge", s0, wrong), $"{wrong}:2: \"faults\" add up to 9, but \"strategyFaults\" is 10");
        string none = Path.Combine(Folder, "none-faults.jsonl");
        File.WriteAllLines(none, [shard1[0], shard1[1].Replace("\"exceptions\":5,\"timeouts\":0,\"badAnswers\":5", "\"exceptions\":0,\"timeouts\":0,\"badAnswers\":0", StringComparison.Ordinal), .. shard1.Skip(2)]);
        AssertError(CliRun.Of(string.Empty, "merge", s0, none), $"{none}:2: \"faults\"[0] must name team 0 to 3 and counts >= 0 that are not all 0");
    }

    [Theory]
    [InlineData("--shard 2/2", "run: --shard must be I/K with 0 <= I < K (e.g. 0/4), got \"2/2\"")]
    [InlineData("--shard one", "run: --shard must be I/K with 0 <= I < K (e.g. 0/4), got \"one\"")]
    [InlineData("--batch 0", "run: --batch must be an integer 1..100000000, got \"0\"")]
    [InlineData("--results r.jsonl", "run: --shard and --results belong to --batch N")]
    [InlineData("--threads 0", "run: --threads must be an integer 1..1024, got \"0\"")]
    [InlineData("--threads 1025", "run: --threads must be an integer 1..1024, got \"1025\"")]
    [InlineData("--crowd 300 --threads two", "run: --threads must be an integer 1..1024, got \"two\"")]
    [InlineData("--batch 2 --trace t.jsonl", "run: --trace, --svg and --html record one match; they do not go with --batch")]
    [InlineData("--crowd 100 --scenario s.json", "run: --item, --scenario and --crowd each choose the scene; give one")]
    [InlineData("--crowd 5", "run: --crowd must be an integer 13..1000000, got \"5\"")]
    public void BadBatchOptionsAreOneUsageLine(string arguments, string message)
    {
        var run = CliRun.Of(string.Empty, ["run", .. arguments.Split(' ')]);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.StartsWith(message + ". Usage: urwpgsim2d run ", run.Stderr, StringComparison.Ordinal);
    }

    private (CliRun Run, string File) Batch(string name, params string[] extra) => Batch(name, 7, extra);

    private (CliRun Run, string File) Batch(string name, int seed, params string[] extra) => Batch(name, seed, 40, extra);

    private (CliRun Run, string File) Batch(string name, int seed, int cycles, params string[] extra)
    {
        string file = Path.Combine(Folder, name + ".jsonl");
        string[] args = ["run", "--batch", "5", "--cycles", cycles.ToString(System.Globalization.CultureInfo.InvariantCulture), "--seed", seed.ToString(System.Globalization.CultureInfo.InvariantCulture), "--results", file, .. extra];
        var run = CliRun.Of(string.Empty, args);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.False(File.Exists(file + ".partial"));
        return (run, file);
    }

    private static string WithoutWallTime(string stdout) =>
        string.Join('\n', stdout.Split('\n').Where(l => !l.StartsWith("wall time:", StringComparison.Ordinal) && !l.StartsWith("wrote ", StringComparison.Ordinal)));

    private static void AssertError(CliRun run, string message)
    {
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.Contains(message, run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
    }
}
