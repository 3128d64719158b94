namespace URWPGSim2D.Server.Tests.Batch.Slurm;

/// <summary>
/// <c>run --batch N --slurm DIR</c> from the command line: it writes the three scripts, which,
/// run as Slurm would run them (each task with its <c>SLURM_ARRAY_TASK_ID</c>, from another
/// directory), play the batch asked for and merge it into the very file one <c>run --batch</c>
/// writes; asked again, it plays only the shards without results; bad options are refused before
/// anything is written.
/// </summary>
public sealed class SlurmRunTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), "urwpg-slurmrun-" + Guid.NewGuid().ToString("N"));
    private readonly string _folder;

    public SlurmRunTests()
    {
        _folder = Path.Combine(_root, "batch 'one' $x");
        Directory.CreateDirectory(_root);
    }

    public void Dispose() => Directory.Delete(_root, recursive: true);

    [Fact]
    public void WritesTheScriptsAndSaysHowToSubmitThem()
    {
        var run = CliRun.Of(string.Empty, "run", "--batch", "8", "--cycles", "3", "--slurm", _folder, "--shards", "4");

        Assert.Equal(string.Empty, run.Stderr);
        Assert.Equal(0, run.ExitCode);
        Assert.Equal(
            $"slurm: 8 matches in 4 shards, in {_folder}; shards to play: 0-3\n" +
            "wrote shards.sbatch, merge.sbatch and submit.sh there\n" +
            $"submit with: bash {ShellWord.Quote(Path.Combine(_folder, "submit.sh"))}\n",
            run.Stdout);
        Assert.True(Directory.Exists(Path.Combine(_folder, "logs")));
        Assert.Contains(" --array=0-3 ", File.ReadAllText(Path.Combine(_folder, "submit.sh")), StringComparison.Ordinal);
        Assert.Equal(["merge.sbatch", "shards.sbatch", "submit.sh"], Directory.GetFiles(_folder).Select(Path.GetFileName).Order(StringComparer.Ordinal));
    }

    [Fact]
    public void TheTasksAndTheMergePlayTheBatchByteForByteAsOneRun()
    {
        string[] batch = ["--batch", "6", "--cycles", "20", "--seed", "5", "--noise", "off", "--strategy-timeout", "50"];
        string merged = Path.Combine(_root, "merged 'all'.jsonl");
        var write = CliRun.Of(string.Empty, ["run", .. batch, "--slurm", _folder, "--shards", "3", "--results", merged]);
        Assert.True(write.ExitCode == 0, write.Stderr);

        for (int i = 0; i < 3; i++)
        {
            var task = Bash.Run(Path.Combine(_folder, "shards.sbatch"), "/", new() { ["SLURM_ARRAY_TASK_ID"] = i.ToString(System.Globalization.CultureInfo.InvariantCulture) });
            Assert.True(task.Code == 0, $"task {i}: {task.Stderr}");
            Assert.Contains($"(shard {i}/3)", task.Stdout, StringComparison.Ordinal);
        }

        var merge = Bash.Run(Path.Combine(_folder, "merge.sbatch"), "/");
        Assert.True(merge.Code == 0, merge.Stderr);

        string local = Path.Combine(_root, "local.jsonl");
        var one = CliRun.Of(string.Empty, ["run", .. batch, "--results", local]);
        Assert.True(one.ExitCode == 0, one.Stderr);
        Assert.Equal(File.ReadAllBytes(local), File.ReadAllBytes(merged));
        Assert.Contains("\"firstSeed\":5,\"matches\":6,\"cycles\":20", File.ReadAllText(merged), StringComparison.Ordinal);
        Assert.Equal(one.Stdout.Split('\n').Skip(6).SkipLast(3), merge.Stdout.Split('\n').SkipLast(2)); // the aggregate, but the wall time and the file lines
    }

    [Fact]
    public void AskedAgainItPlaysOnlyTheShardsWithoutResults()
    {
        Directory.CreateDirectory(_folder);
        for (int i = 0; i < 4; i++)
        {
            var shard = CliRun.Of(string.Empty, "run", "--batch", "8", "--cycles", "3", "--shard", $"{i}/4", "--threads", "1", "--results", Path.Combine(_folder, $"shard-{i}.jsonl"));
            Assert.True(shard.ExitCode == 0, shard.Stderr);
        }

        File.Move(Path.Combine(_folder, "shard-2.jsonl"), Path.Combine(_folder, "shard-2.jsonl.partial"));
        var run = CliRun.Of(string.Empty, "run", "--batch", "8", "--cycles", "3", "--slurm", _folder, "--shards", "4");

        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.StartsWith($"slurm: 8 matches in 4 shards, in {_folder}; shards to play: 2\n", run.Stdout, StringComparison.Ordinal);
        Assert.Contains(" --array=2 ", File.ReadAllText(Path.Combine(_folder, "submit.sh")), StringComparison.Ordinal);

        File.Delete(Path.Combine(_folder, "shard-2.jsonl.partial"));
        File.Copy(Path.Combine(_folder, "shard-1.jsonl"), Path.Combine(_folder, "shard-2.jsonl"));
        run = CliRun.Of(string.Empty, "run", "--batch", "8", "--cycles", "3", "--slurm", _folder, "--shards", "4");
        Assert.Equal(2, run.ExitCode);
        Assert.Equal($"run: {Path.Combine(_folder, "shard-2.jsonl")}: holds shard 1/4, not 2/4\n", run.Stderr);
    }

    [Theory]
    [InlineData("run: --shards, --partition, --time, --sbatch-arg, --slurm-setup and --submit belong to --slurm DIR", "--batch", "8", "--shards", "4")]
    [InlineData("run: --shards, --partition, --time, --sbatch-arg, --slurm-setup and --submit belong to --slurm DIR", "--batch", "8", "--submit")]
    [InlineData("run: --slurm DIR belongs to --batch N", "--slurm", "DIR")]
    [InlineData("run: --slurm makes the shards itself (--shards K); --shard I/K does not go with it", "--batch", "8", "--slurm", "DIR", "--shard", "1/4")]
    [InlineData("run: --shards 9 is more than the 8 matches of --batch", "--batch", "8", "--slurm", "DIR", "--shards", "9")]
    [InlineData("run: --shards must be an integer 1..1000, got \"1001\"", "--batch", "2000", "--slurm", "DIR", "--shards", "1001")]
    [InlineData("run: --time must be a Slurm time limit (M, M:S, H:M:S, D-H, D-H:M, D-H:M:S or infinite), got \"1h\"", "--batch", "8", "--slurm", "DIR", "--time", "1h")]
    [InlineData("run: --partition must be a Slurm partition name (letters, digits, '_', '-', '.', comma-separated), got \"a b\"", "--batch", "8", "--slurm", "DIR", "--partition", "a b")]
    [InlineData("run: --scenario - (standard input) cannot be read again by the Slurm tasks; give a file", "--batch", "8", "--slurm", "DIR", "--scenario", "-")]
    [InlineData("run: --submit given twice", "--batch", "8", "--slurm", "DIR", "--submit", "--submit")]
    public void BadOptionsAreOneLineAndExitTwoWithNothingWritten(string message, params string[] options)
    {
        var run = CliRun.Of(string.Empty, ["run", .. options.Select(o => o == "DIR" ? _folder : o)]);

        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith(message, run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
        Assert.False(Directory.Exists(_folder));
    }

    [Fact]
    public void BadPathsAreOneLineAndExitTwoWithNothingWritten()
    {
        string file = Path.Combine(_root, "a file");
        File.WriteAllText(file, "x");
        var run = CliRun.Of(string.Empty, "run", "--batch", "8", "--slurm", file);
        Assert.Equal((2, $"run: --slurm: {file} is a file, not a folder\n"), (run.ExitCode, run.Stderr));

        string nowhere = Path.Combine(_root, "nowhere", "all.jsonl");
        run = CliRun.Of(string.Empty, "run", "--batch", "8", "--slurm", _folder, "--results", nowhere);
        Assert.Equal((2, $"run: --results: the folder {Path.GetDirectoryName(nowhere)} does not exist\n"), (run.ExitCode, run.Stderr));
        Assert.False(Directory.Exists(_folder));
    }

    [Fact]
    public void SbatchArgumentsAndTheSetupFileGoIntoTheScriptsAndNotToTheTasks()
    {
        string setup = Path.Combine(_root, "setup.sh");
        File.WriteAllText(setup, "module load dotnet\n");
        var run = CliRun.Of(string.Empty, "run", "--batch", "8", "--cycles", "3", "--slurm", _folder, "--sbatch-arg", "--account=fish", "--sbatch-arg", "--mem=4G", "--slurm-setup", setup);

        Assert.True(run.ExitCode == 0, run.Stderr);
        string submit = File.ReadAllText(Path.Combine(_folder, "submit.sh"));
        Assert.Equal(2, submit.Split(" --account=fish --mem=4G --chdir=").Length - 1); // both jobs
        foreach (string script in new[] { "shards.sbatch", "merge.sbatch" })
        {
            string text = File.ReadAllText(Path.Combine(_folder, script));
            Assert.Contains("\nsource " + ShellWord.Quote(setup) + " ", text, StringComparison.Ordinal);
            Assert.DoesNotContain("--account", text.Split('\n').Single(l => l.StartsWith("exec ", StringComparison.Ordinal)), StringComparison.Ordinal);
        }

        var missing = CliRun.Of(string.Empty, "run", "--batch", "8", "--slurm", Path.Combine(_root, "other"), "--slurm-setup", Path.Combine(_root, "none.sh"));
        Assert.Equal((2, $"run: --slurm-setup: {Path.Combine(_root, "none.sh")} is not a file (a bash file the jobs source before the server starts)\n"), (missing.ExitCode, missing.Stderr));
        Assert.False(Directory.Exists(Path.Combine(_root, "other")));

        var own = CliRun.Of(string.Empty, "run", "--batch", "8", "--slurm", Path.Combine(_root, "other"), "--sbatch-arg", "--array=0-3");
        Assert.Equal(2, own.ExitCode);
        Assert.StartsWith("run: --sbatch-arg --array: the scripts set --array themselves. Usage: ", own.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async System.Threading.Tasks.Task ARefusedSubmissionShowsSbatchsMessageAsWrittenAndExitsTwo()
    {
        // A stand-in sbatch that refuses as a cluster does without --account: two lines on stderr, exit 1.
        string bin = Path.Combine(_root, "bin");
        Directory.CreateDirectory(bin);
        string sbatch = Path.Combine(bin, "sbatch");
        File.WriteAllText(sbatch, "#!/bin/bash\necho 'sbatch: error: Batch job submission failed: Invalid account' >&2\necho 'sbatch: error: (give --account)' >&2\nexit 1\n");
        if (!OperatingSystem.IsWindows())
        {
            File.SetUnixFileMode(sbatch, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
        }

        string server = Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll");
        var start = new System.Diagnostics.ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string a in new[] { server, "run", "--batch", "4", "--cycles", "3", "--slurm", _folder, "--submit" })
        {
            start.ArgumentList.Add(a);
        }

        start.Environment["PATH"] = bin + ":" + Environment.GetEnvironmentVariable("PATH");
        using var process = System.Diagnostics.Process.Start(start)!;
        var error = process.StandardError.ReadToEndAsync();
        string stdout = await process.StandardOutput.ReadToEndAsync();
        string stderr = await error;
        Assert.True(process.WaitForExit(60_000));

        Assert.Equal(2, process.ExitCode);
        Assert.StartsWith($"slurm: 4 matches in 4 shards, in {_folder}; shards to play: 0-3\n", stdout, StringComparison.Ordinal);
        Assert.Equal(
            $"run: --submit: sbatch refused the jobs (bash {ShellWord.Quote(Path.Combine(_folder, "submit.sh"))} exited 1); its message:\n" +
            "sbatch: error: Batch job submission failed: Invalid account\n" +
            "sbatch: error: (give --account)\n",
            stderr);
    }

    [Fact]
    public void TheTasksGetEveryOptionButThoseOfSlurmInTheirOrder()
    {
        var options = RunOptions.Parse([
            "--scenario", "--submit", "--slurm", "d", "--batch", "8", "--shards", "2", "--strategy", "0=a.dll", "--partition", "p",
            "--time", "10", "--strategy", "1=b.dll", "--sbatch-arg", "--qos=x", "--results", "r.jsonl", "--slurm-setup", "s.sh", "--submit", "--seed", "3"]);

        Assert.Equal(["--scenario", "--submit", "--batch", "8", "--strategy", "0=a.dll", "--strategy", "1=b.dll", "--seed", "3"], options.PassedOn);
        Assert.Equal(["--qos=x"], options.SbatchArguments);
        Assert.Equal("s.sh", options.SlurmSetup);
        Assert.Equal(("--submit", "d", 2, "p", "10", "r.jsonl", true), (options.Scenario, options.Slurm, options.SlurmShards, options.Partition, options.TimeLimit, options.Results, options.Submit));
    }
}
