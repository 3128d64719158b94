namespace URWPGSim2D.Server.Tests.Batch.Slurm;

/// <summary>
/// The scripts of <see cref="SlurmJob"/>, run by bash with stand-ins for the server and for
/// sbatch that record what they were called with: every path (spaces, quotes, <c>$</c> and all)
/// arrives as one argument, the tasks run in the directory the batch was asked from whatever
/// their own, the array holds exactly the shards to play and the merge job depends on it.
/// </summary>
public sealed class SlurmJobTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), "urwpg-slurmjob-" + Guid.NewGuid().ToString("N"));
    private readonly string _folder;
    private readonly string _asked;
    private readonly string _record;

    public SlurmJobTests()
    {
        _folder = Path.Combine(_root, "batch dir 'q' \"d\" $x %a");
        _asked = Path.Combine(_root, "asked from $(here)");
        _record = Path.Combine(_root, "calls");
        Directory.CreateDirectory(_folder);
        Directory.CreateDirectory(_asked);
    }

    public void Dispose() => Directory.Delete(_root, recursive: true);

    [Fact]
    public void TaskIPlaysShardIOfKInTheAskingDirectoryWithEveryOptionPassedOn()
    {
        string[] options = ["--batch", "8", "--scenario", "my scene's.json", "--strategy", "0=it's.dll", "--seed", "7", "--noise", "off"];
        var job = Job(options, threads: null);
        string script = Write(SlurmJob.ShardScriptName, job.ShardScript());

        var (code, _, stderr) = Bash.Run(script, "/", new() { ["RECORD"] = _record, ["SLURM_ARRAY_TASK_ID"] = "2" });

        Assert.True(code == 0, stderr);
        var call = Assert.Single(Bash.Records(_record));
        Assert.Equal(_asked, call[0]);
        Assert.Equal(
            ["run", .. options, "--threads", "1", "--shard", "2/4", "--results", Path.Combine(_folder, "shard-2.jsonl"), "--force"],
            call[1..]);
    }

    [Fact]
    public void AThreadsOptionIsPassedOnAsGivenAndNotAddedTwice()
    {
        var job = Job(["--batch", "8", "--threads", "3"], threads: 3);
        string script = Write(SlurmJob.ShardScriptName, job.ShardScript());

        var (code, _, stderr) = Bash.Run(script, _root, new() { ["RECORD"] = _record, ["SLURM_ARRAY_TASK_ID"] = "0" });

        Assert.True(code == 0, stderr);
        Assert.Equal(
            ["run", "--batch", "8", "--threads", "3", "--shard", "0/4", "--results", Path.Combine(_folder, "shard-0.jsonl"), "--force"],
            Assert.Single(Bash.Records(_record))[1..]);
    }

    [Fact]
    public void WhereTheBatchWasAskedFromIsNotOnTheNodeTheTaskSaysSoAndRunsInTheFolder()
    {
        var job = Job(["--batch", "8"]) with { WorkingDirectory = Path.Combine(_root, "gone 'x'") };
        string script = Write(SlurmJob.ShardScriptName, job.ShardScript());

        var (code, _, stderr) = Bash.Run(script, "/", new() { ["RECORD"] = _record, ["SLURM_ARRAY_TASK_ID"] = "1" });

        Assert.True(code == 0, stderr);
        Assert.Equal(
            $"shards.sbatch: {Path.Combine(_root, "gone 'x'")} (where the batch was asked from) is not on this node: running in {_folder}, where relative paths of the options are not found\n",
            stderr);
        Assert.Equal(_folder, Assert.Single(Bash.Records(_record))[0]);
    }

    [Fact]
    public void TheTaskScriptOutsideAJobArrayStopsWithoutStartingTheServer()
    {
        string script = Write(SlurmJob.ShardScriptName, Job(["--batch", "8"]).ShardScript());

        var (code, _, stderr) = Bash.Run(script, _root, new() { ["RECORD"] = _record, ["SLURM_ARRAY_TASK_ID"] = null });

        Assert.NotEqual(0, code);
        Assert.Contains("not a task of a Slurm job array", stderr, StringComparison.Ordinal);
        Assert.False(File.Exists(_record));
    }

    [Fact]
    public void TheMergeJobMergesEveryShardIntoTheResultsFile()
    {
        string results = Path.Combine(_root, "all 'results'.jsonl");
        string script = Write(SlurmJob.MergeScriptName, (Job(["--batch", "8"]) with { Results = results }).MergeScript());

        var (code, _, stderr) = Bash.Run(script, "/", new() { ["RECORD"] = _record });

        Assert.True(code == 0, stderr);
        Assert.Equal(
            ["merge", "--out", results, "--force", .. Enumerable.Range(0, 4).Select(i => Path.Combine(_folder, $"shard-{i}.jsonl"))],
            Assert.Single(Bash.Records(_record))[1..]);
    }

    [Fact]
    public void SubmitSubmitsTheShardsToPlayThenTheMergeAfterThem()
    {
        var job = Job(["--batch", "8"], threads: 2) with { ToPlay = [1, 3], Partition = "short", TimeLimit = "0-00:30" };
        var (calls, stdout) = Submit(job, "41", "42;cluster");

        Assert.Equal(2, calls.Count);
        Assert.Equal(
            ["--parsable", "--job-name=urwpg-shards", "--array=1,3", "--cpus-per-task=2", "--partition=short", "--time=0-00:30",
                "--chdir=" + _folder, "--output=logs/shard-%a.txt", Path.Combine(_folder, "shards.sbatch")],
            calls[0][1..]);
        Assert.Equal(
            ["--parsable", "--job-name=urwpg-merge", "--dependency=afterok:41", "--kill-on-invalid-dep=yes", "--partition=short", "--time=0-00:30",
                "--chdir=" + _folder, "--output=logs/merge.txt", Path.Combine(_folder, "merge.sbatch")],
            calls[1][1..]);
        Assert.Equal(
            $"array job 41: shards 1,3 of 4, results in {_folder}/shard-I.jsonl, logs in {_folder}/logs/shard-I.txt\n" +
            $"merge job 42: after array job 41 succeeds, writes {Path.Combine(_folder, "results.jsonl")}\n",
            stdout);
    }

    [Fact]
    public void WithEveryShardDoneOnlyTheMergeIsSubmitted()
    {
        var (calls, stdout) = Submit(Job(["--batch", "8"]) with { ToPlay = [] }, "57");

        var call = Assert.Single(calls);
        Assert.Equal(["--parsable", "--job-name=urwpg-merge", "--chdir=" + _folder, "--output=logs/merge.txt", Path.Combine(_folder, "merge.sbatch")], call[1..]);
        Assert.Equal($"no array job: all 4 shards have their results\nmerge job 57: writes {Path.Combine(_folder, "results.jsonl")}\n", stdout);
    }

    [Fact]
    public void ARefusedSubmissionStopsTheScript()
    {
        var (code, stdout, _) = RunSubmit(Job(["--batch", "8"]), "exit 1\n");

        Assert.NotEqual(0, code);
        Assert.Single(Bash.Records(_record)); // the merge job is not submitted
        Assert.Equal(string.Empty, stdout);
    }

    [Fact]
    public void WhenOnlyTheMergeIsRefusedTheArrayJobIsStillReported()
    {
        var (code, stdout, _) = RunSubmit(Job(["--batch", "8"]), "[ -e \"$RECORD.n\" ] && exit 1\ntouch \"$RECORD.n\"\necho 41\n");

        Assert.NotEqual(0, code);
        Assert.Equal(2, Bash.Records(_record).Count);
        Assert.StartsWith("array job 41: shards 0-3 of 4, ", stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("merge job", stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void TheEnvironmentNamesTheDotnetHostAndTheServerTheJobsRun()
    {
        // URWPGSIM2D_SERVER: another server (a program: run as is; a .dll: with the dotnet host),
        // URWPGSIM2D_DOTNET: another dotnet host. Both jobs follow them.
        string other = Bash.Recorder(Path.Combine(_root, "other server"), "echo program >> \"$RECORD.who\"\n");
        string host = Bash.Recorder(Path.Combine(_root, "my dotnet"), "echo host >> \"$RECORD.who\"\n");
        var job = Job(["--batch", "8"]);
        string shards = Write(SlurmJob.ShardScriptName, job.ShardScript());
        string merge = Write(SlurmJob.MergeScriptName, job.MergeScript());

        var (code, _, stderr) = Bash.Run(shards, "/", new() { ["RECORD"] = _record, ["SLURM_ARRAY_TASK_ID"] = "0", [SlurmJob.ServerVariable] = other });
        Assert.True(code == 0, stderr);
        (code, _, stderr) = Bash.Run(merge, "/", new() { ["RECORD"] = _record, [SlurmJob.DotnetVariable] = host });
        Assert.True(code == 0, stderr);

        var calls = Bash.Records(_record);
        Assert.Equal(2, calls.Count);
        Assert.Equal("run", calls[0][1]); // the program itself, its first argument the command
        Assert.Equal([ServerScript, "merge"], calls[1][1..3]); // the host, given the default server DLL
        Assert.Equal(["program", "host"], File.ReadAllLines(_record + ".who"));
    }

    [Fact]
    public void ADefaultDotnetHostMissingOnTheNodeGivesWayToTheOneOnPath()
    {
        // The scripts were written where dotnet is /nowhere/dotnet; on the node a module puts dotnet on PATH.
        string bin = Path.Combine(_root, "module bin");
        Directory.CreateDirectory(bin);
        Bash.Recorder(Path.Combine(bin, "dotnet"));
        var job = Job(["--batch", "8"]) with { Server = ["/nowhere/dotnet", ServerScript] };
        string merge = Write(SlurmJob.MergeScriptName, job.MergeScript());

        var (code, _, stderr) = Bash.Run(merge, "/", new() { ["RECORD"] = _record, ["PATH"] = bin + ":" + Environment.GetEnvironmentVariable("PATH") });

        Assert.True(code == 0, stderr);
        Assert.Equal([ServerScript, "merge"], Assert.Single(Bash.Records(_record))[1..3]);
    }

    [Fact]
    public void TheSetupFileIsSourcedByBothJobsBeforeTheServerStarts()
    {
        // A setup file in the style of a module load: it reads an unset variable and puts dotnet on PATH.
        string bin = Path.Combine(_root, "module 'bin'");
        Directory.CreateDirectory(bin);
        Bash.Recorder(Path.Combine(bin, "dotnet"));
        string setup = Path.Combine(_root, "setup $x.sh");
        File.WriteAllText(setup, $"[ -z \"$MODULES_UNSET_VARIABLE\" ] && export PATH={ShellWord.Quote(bin)}:\"$PATH\"\necho sourced >> \"$RECORD.setup\"\n");
        var job = Job(["--batch", "8"]) with { Server = ["/nowhere/dotnet", ServerScript], Setup = setup };

        foreach (var (name, text) in new[] { (SlurmJob.ShardScriptName, job.ShardScript()), (SlurmJob.MergeScriptName, job.MergeScript()) })
        {
            var (code, _, stderr) = Bash.Run(Write(name, text), "/", new() { ["RECORD"] = _record, ["SLURM_ARRAY_TASK_ID"] = "1" });
            Assert.True(code == 0, name + ": " + stderr);
        }

        Assert.Equal(["sourced", "sourced"], File.ReadAllLines(_record + ".setup"));
        Assert.Equal(2, Bash.Records(_record).Count);

        // A setup that fails stops the job before the server starts.
        File.WriteAllText(setup, "false\n");
        var failed = Bash.Run(Write(SlurmJob.MergeScriptName, job.MergeScript()), "/", new() { ["RECORD"] = _record });
        Assert.NotEqual(0, failed.Code);
        Assert.Equal(2, Bash.Records(_record).Count);
    }

    [Fact]
    public void SbatchArgumentsGoToBothJobsInOrder()
    {
        string[] extra = ["--account=fish 'team'", "--qos=normal", "--mem=4G"];
        var job = Job(["--batch", "8"]) with { ToPlay = [2], SbatchArguments = extra };
        var (calls, _) = Submit(job, "41", "42");

        Assert.Equal(2, calls.Count);
        Assert.All(calls, c => Assert.Equal(extra, c.Skip(c.ToList().IndexOf("--chdir=" + _folder) - extra.Length).Take(extra.Length)));
    }

    [Theory]
    [InlineData("--account=fish", null)]
    [InlineData("-A", null)]
    [InlineData("--mem=4G", null)]
    [InlineData("account=fish", "--sbatch-arg must be one sbatch option such as --account=NAME or --mem=4G (one word; NAME after '=')")]
    [InlineData("-", "--sbatch-arg must be one sbatch option such as --account=NAME or --mem=4G (one word; NAME after '=')")]
    [InlineData("--array=1-3", "--sbatch-arg --array: the scripts set --array themselves")]
    [InlineData("--dependency=afterok:1", "--sbatch-arg --dependency: the scripts set --dependency themselves")]
    [InlineData("-ologs/x.txt", "--sbatch-arg -ologs/x.txt: the scripts set -o themselves")]
    public void SbatchArgumentsAreOptionWordsTheScriptsDoNotSetThemselves(string value, string? error)
    {
        string? why = SlurmJob.SbatchArgumentError(value);
        Assert.Equal(error, why);
    }

    [Theory]
    [InlineData("60", true)]
    [InlineData("1:30", true)]
    [InlineData("2:00:00", true)]
    [InlineData("1-12", true)]
    [InlineData("1-12:30", true)]
    [InlineData("1-12:30:00", true)]
    [InlineData("infinite", true)]
    [InlineData("UNLIMITED", true)]
    [InlineData("", false)]
    [InlineData("1h", false)]
    [InlineData("1:2:3:4", false)]
    [InlineData("-5", false)]
    [InlineData("1 ; rm", false)]
    [InlineData("\u0661\u0662", false)]
    public void TimeLimitsAreSbatchFormats(string value, bool valid) => Assert.Equal(valid, SlurmJob.IsTimeLimit(value));

    [Theory]
    [InlineData("debug", true)]
    [InlineData("gpu-a100_x.2", true)]
    [InlineData("short,long", true)]
    [InlineData("", false)]
    [InlineData("a b", false)]
    [InlineData("a,", false)]
    [InlineData("x'y", false)]
    public void PartitionsAreNames(string value, bool valid) => Assert.Equal(valid, SlurmJob.IsPartition(value));

    // The server stand-in: bash on a recorder named like a DLL in a folder with a difficult name, like dotnet on a DLL.
    private string ServerScript => Path.Combine(_root, "server's \"bin\"", "server.dll");

    private SlurmJob Job(string[] options, int? threads = null)
    {
        Directory.CreateDirectory(Path.GetDirectoryName(ServerScript)!);
        Bash.Recorder(ServerScript);
        return new SlurmJob(
            ["bash", ServerScript], options, _asked, _folder, Path.Combine(_folder, "results.jsonl"), 4, [0, 1, 2, 3],
            threads ?? 1, threads is not null, null, null);
    }

    private (List<string[]> Calls, string Stdout) Submit(SlurmJob job, params string[] ids)
    {
        // The stand-in sbatch prints the next id of the list at each call.
        string lines = "n=$(grep -c '' \"$RECORD.n\" 2>/dev/null || true); echo x >> \"$RECORD.n\"\nids=(" + string.Join(" ", ids.Select(ShellWord.Quote)) + ")\necho \"${ids[$n]}\"\n";
        var (code, stdout, stderr) = RunSubmit(job, lines);
        Assert.True(code == 0, stderr);
        return (Bash.Records(_record), stdout);
    }

    private (int Code, string Stdout, string Stderr) RunSubmit(SlurmJob job, string sbatchBody)
    {
        string bin = Path.Combine(_root, "bin");
        Directory.CreateDirectory(bin);
        Bash.Recorder(Path.Combine(bin, "sbatch"), sbatchBody);
        string script = Write(SlurmJob.SubmitScriptName, job.SubmitScript());
        return Bash.Run(script, "/", new() { ["RECORD"] = _record, ["PATH"] = bin + ":" + Environment.GetEnvironmentVariable("PATH") });
    }

    private string Write(string name, string text)
    {
        string path = Path.Combine(_folder, name);
        File.WriteAllText(path, text);
        return path;
    }
}
