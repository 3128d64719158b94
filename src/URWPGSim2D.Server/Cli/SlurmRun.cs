using System.Diagnostics;
using URWPGSim2D.Tournament.Batch;
using URWPGSim2D.Tournament.Batch.Slurm;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>run --batch N --slurm DIR</c>: writes the batch's Slurm scripts into DIR (see
/// <see cref="SlurmJob"/>) for the shards whose results are missing or incomplete there, and with
/// <c>--submit</c> submits them (<c>bash DIR/submit.sh</c>) and prints the job ids. Everything is
/// checked before anything is written: a problem is one line on stderr and exit code 2.
/// </summary>
internal static class SlurmRun
{
    /// <summary>Writes (and submits) the batch's jobs; returns the exit code.</summary>
    public static int Run(RunOptions options, BatchHeader header, CliConsole console)
    {
        string folder, results;
        try
        {
            folder = Path.TrimEndingDirectorySeparator(Path.GetFullPath(options.Slurm!));
            results = Path.GetFullPath(options.Results ?? Path.Combine(folder, "results.jsonl"));
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
            return Refuse(console, $"--slurm: not a usable path ({e.Message})");
        }

        if (File.Exists(folder))
        {
            return Refuse(console, $"--slurm: {folder} is a file, not a folder");
        }

        string? resultsFolder = Path.GetDirectoryName(results);
        if (Directory.Exists(results) || resultsFolder is null)
        {
            return Refuse(console, $"--results: {results} is a folder");
        }

        if (resultsFolder != folder && !Directory.Exists(resultsFolder))
        {
            return Refuse(console, $"--results: the folder {resultsFolder} does not exist");
        }

        if (options.Submit && (OnPath("sbatch") is null || OnPath("bash") is null))
        {
            return Refuse(console, "--submit: sbatch (or bash) is not on PATH; submit from a Slurm login node, or leave out --submit and run submit.sh there");
        }

        int shards = options.SlurmShards ?? SlurmJob.DefaultShards(header.Matches);
        List<int> toPlay;
        try
        {
            toPlay = ShardResults.ToPlay(folder, header.Whole, shards);
        }
        catch (ResultFileException e)
        {
            return Refuse(console, e.Message);
        }

        if (Setup(options.SlurmSetup, console, "run") is not { } setup)
        {
            return ExitCodes.BadInput;
        }

        var job = new SlurmJob(
            ServerCommand.OfThisProcess(), options.PassedOn, Environment.CurrentDirectory, folder, results, shards, toPlay,
            options.Threads ?? 1, options.Threads is not null, options.Partition, options.TimeLimit,
            SbatchArguments: options.SbatchArguments, Setup: setup.Length > 0 ? setup : null);
        return WriteJobs(job, header.Matches, options.Submit, console, "run");
    }

    /// <summary>
    /// The absolute path of <c>--slurm-setup FILE</c> (empty without the option), or null after a
    /// line on stderr when FILE is not a readable file.
    /// </summary>
    internal static string? Setup(string? file, CliConsole console, string command)
    {
        if (file is null)
        {
            return string.Empty;
        }

        try
        {
            string full = Path.GetFullPath(file);
            if (File.Exists(full))
            {
                return full;
            }
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
        }

        console.ErrorLine($"{command}: --slurm-setup: {file} is not a file (a bash file the jobs source before the server starts)");
        return null;
    }

    /// <summary>
    /// Writes a job's three scripts into its folder, says what they play, and with
    /// <paramref name="submit"/> submits them; returns the exit code (shared by <c>run --batch</c> and <c>tournament</c>).
    /// </summary>
    /// <param name="job">The job.</param>
    /// <param name="matches">The matches of the whole batch or tournament.</param>
    /// <param name="submit">Whether to submit (sbatch was checked to be on PATH).</param>
    /// <param name="console">The streams.</param>
    /// <param name="command">The command's name for error lines.</param>
    internal static int WriteJobs(SlurmJob job, int matches, bool submit, CliConsole console, string command)
    {
        string folder = job.Folder;
        string submitScript = Path.Combine(folder, SlurmJob.SubmitScriptName);
        try
        {
            Directory.CreateDirectory(Path.Combine(folder, SlurmJob.LogFolder));
            WriteScript(Path.Combine(folder, SlurmJob.ShardScriptName), job.ShardScript());
            WriteScript(Path.Combine(folder, SlurmJob.MergeScriptName), job.MergeScript());
            WriteScript(submitScript, job.SubmitScript());
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            console.ErrorLine($"{command}: --slurm: cannot write the scripts into {folder} ({e.Message})");
            return ExitCodes.BadInput;
        }

        string play = job.ToPlay.Count == 0 ? "none (all have results)" : ArraySpec.Format(job.ToPlay);
        console.Out.Write($"slurm: {matches} matches in {job.Shards} shards, in {folder}; shards to play: {play}\n");
        console.Out.Write($"wrote {SlurmJob.ShardScriptName}, {SlurmJob.MergeScriptName} and {SlurmJob.SubmitScriptName} there\n");
        if (!submit)
        {
            console.Out.Write($"submit with: bash {ShellWord.Quote(submitScript)}\n");
            return ExitCodes.Success;
        }

        return Submit(submitScript, console, command);
    }

    // bash DIR/submit.sh: its lines (the job ids) go to stdout; when sbatch refuses, a line saying so
    // and sbatch's message as it wrote it go to stderr, exit code 2.
    private static int Submit(string script, CliConsole console, string command)
    {
        var start = new ProcessStartInfo("bash") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(script);
        using var process = Process.Start(start)!;
        var error = process.StandardError.ReadToEndAsync();
        string output = process.StandardOutput.ReadToEnd();
        process.WaitForExit();
        console.Out.Write(output);
        if (process.ExitCode != 0)
        {
            string message = error.Result.TrimEnd();
            console.ErrorLine($"{command}: --submit: sbatch refused the jobs (bash {ShellWord.Quote(script)} exited {process.ExitCode}){(message.Length > 0 ? "; its message:" : string.Empty)}");
            foreach (string line in message.Split('\n'))
            {
                if (line.Length > 0)
                {
                    console.ErrorLine(line.TrimEnd('\r'));
                }
            }

            return ExitCodes.BadInput;
        }

        return ExitCodes.Success;
    }

    // Written whole and renamed, so a script is never half there; executable for its owner.
    private static void WriteScript(string path, string text)
    {
        string temporary = path + ".tmp";
        File.WriteAllText(temporary, text);
        if (!OperatingSystem.IsWindows())
        {
            File.SetUnixFileMode(temporary, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute | UnixFileMode.GroupRead | UnixFileMode.GroupExecute | UnixFileMode.OtherRead | UnixFileMode.OtherExecute);
        }

        File.Move(temporary, path, overwrite: true);
    }

    /// <summary>The full path of <paramref name="program"/> on PATH, or null.</summary>
    internal static string? OnPath(string program) =>
        (Environment.GetEnvironmentVariable("PATH") ?? string.Empty)
            .Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries)
            .Select(d => Path.Combine(d, program))
            .FirstOrDefault(File.Exists);

    private static int Refuse(CliConsole console, string message)
    {
        console.ErrorLine("run: " + message);
        return ExitCodes.BadInput;
    }
}
