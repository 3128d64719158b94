using System.Text.RegularExpressions;

namespace URWPGSim2D.Tournament.Batch.Slurm;

/// <summary>
/// A batch as Slurm jobs, and the three scripts that run it from its folder: <c>shards.sbatch</c>
/// (task I of a job array plays shard I of K and writes <c>shard-I.jsonl</c>), <c>merge.sbatch</c>
/// (merges the K files into the results file) and <c>submit.sh</c> (submits the array of the shards
/// still to play, then the merge job with <c>--dependency=afterok</c> on the array). Every path in
/// them is absolute and every word shell-quoted, so they run from any working directory; the tasks
/// <c>cd</c> to the directory the batch was asked from, so relative paths among the passed-on
/// options (a scenario, a strategy) mean what they meant there (when that directory is not on the
/// node, a task says so in its log and runs in the batch's folder). The jobs start the server that
/// wrote them unless the environment variables <see cref="DotnetVariable"/> and
/// <see cref="ServerVariable"/> say otherwise, after sourcing the <see cref="Setup"/> file if any.
/// </summary>
/// <param name="Server">The command words that start the server (the running server's dotnet host and DLL, or its program, by absolute paths).</param>
/// <param name="RunArguments">The options of <c>run</c> every task passes on (the batch, its scene, cycles, seed, noise, strategies…).</param>
/// <param name="WorkingDirectory">The absolute directory the batch was asked from.</param>
/// <param name="Folder">The batch's absolute folder: scripts, shard files, <c>logs/</c>.</param>
/// <param name="Results">The absolute path of the merged results file.</param>
/// <param name="Shards">K, the number of shards.</param>
/// <param name="ToPlay">The shards the array plays (those without a complete result file), increasing.</param>
/// <param name="Cpus">CPUs per task, and the task's <c>--threads</c> when none is passed on.</param>
/// <param name="ThreadsPassedOn">Whether <paramref name="RunArguments"/> holds <c>--threads</c>.</param>
/// <param name="Partition">sbatch's <c>--partition</c>, or null.</param>
/// <param name="TimeLimit">sbatch's <c>--time</c>, or null.</param>
/// <param name="Command">The server's command the tasks run with <paramref name="RunArguments"/>: <c>run</c> (a batch) or <c>tournament</c>.</param>
/// <param name="MergeArguments">The merge job's command words before the shard files, or null for <c>merge --out RESULTS</c> (a batch's).</param>
/// <param name="SbatchArguments">Further sbatch options for both jobs (<c>--sbatch-arg</c>: <c>--account=A</c>, <c>--qos=Q</c>, <c>--mem=M</c>…), in order, or null.</param>
/// <param name="Setup">The absolute path of a bash file both job scripts source before the server starts (<c>--slurm-setup</c>: module loads, environment), or null.</param>
public sealed partial record SlurmJob(
    IReadOnlyList<string> Server,
    IReadOnlyList<string> RunArguments,
    string WorkingDirectory,
    string Folder,
    string Results,
    int Shards,
    IReadOnlyList<int> ToPlay,
    int Cpus,
    bool ThreadsPassedOn,
    string? Partition,
    string? TimeLimit,
    string Command = "run",
    IReadOnlyList<string>? MergeArguments = null,
    IReadOnlyList<string>? SbatchArguments = null,
    string? Setup = null)
{
    /// <summary>The environment variable that names the <c>dotnet</c> host the jobs run a server DLL with.</summary>
    public const string DotnetVariable = "URWPGSIM2D_DOTNET";

    /// <summary>The environment variable that names the server the jobs run: a <c>.dll</c> (run with <c>dotnet</c>) or a program.</summary>
    public const string ServerVariable = "URWPGSIM2D_SERVER";

    /// <summary>sbatch options the scripts set themselves, refused in <c>--sbatch-arg</c>.</summary>
    private static readonly string[] OwnSbatchOptions = ["--array", "-a", "--dependency", "-d", "--parsable", "--chdir", "-D", "--output", "-o", "--wrap", "--kill-on-invalid-dep"];

    /// <summary>Why <paramref name="value"/> cannot be an <c>--sbatch-arg</c>, or null when it can: one sbatch option word such as <c>--account=fish</c>.</summary>
    public static string? SbatchArgumentError(string value)
    {
        ArgumentNullException.ThrowIfNull(value);
        if (!value.StartsWith('-') || value.Length < 2 || value.Any(char.IsControl))
        {
            return "--sbatch-arg must be one sbatch option such as --account=NAME or --mem=4G (one word; NAME after '=')";
        }

        string name = value.Split('=')[0];
        string? own = OwnSbatchOptions.Contains(name) ? name
            : name.Length > 2 && name[1] != '-' && OwnSbatchOptions.Contains(name[..2]) ? name[..2] // -ologs/x.txt
            : null;
        if (own is not null)
        {
            return $"--sbatch-arg {name}: the scripts set {own} themselves";
        }

        return null;
    }

    /// <summary>Most shards of one batch: task indices 0 … 999 fit Slurm's default <c>MaxArraySize</c> (1001).</summary>
    public const int MaximumShards = 1000;

    /// <summary>Shards of a batch of <c>--batch N</c> when <c>--shards</c> is not given: 10, or N when fewer.</summary>
    public static int DefaultShards(int matches) => Math.Min(matches, 10);

    /// <summary>The script of the array's tasks.</summary>
    public const string ShardScriptName = "shards.sbatch";

    /// <summary>The script of the merge job.</summary>
    public const string MergeScriptName = "merge.sbatch";

    /// <summary>The script that submits both.</summary>
    public const string SubmitScriptName = "submit.sh";

    /// <summary>The logs' sub-folder of the batch's folder.</summary>
    public const string LogFolder = "logs";

    /// <summary>Whether <paramref name="value"/> is a Slurm partition name, or a comma-separated list of them.</summary>
    public static bool IsPartition(string value) => Partitions().IsMatch(value);

    /// <summary>Whether <paramref name="value"/> is a time limit sbatch takes: M, M:S, H:M:S, D-H, D-H:M, D-H:M:S, infinite or unlimited.</summary>
    public static bool IsTimeLimit(string value) => TimeLimits().IsMatch(value);

    /// <summary>The text of <c>shards.sbatch</c>.</summary>
    public string ShardScript()
    {
        var s = Script(
            "Task I of a Slurm job array: plays shard I of the batch and writes shard-I.jsonl.",
            "Submitted by submit.sh, next to this file.");
        s.Append("shard=${SLURM_ARRAY_TASK_ID:?not a task of a Slurm job array: submit with submit.sh}\n");
        s.Append("folder=").Append(ShellWord.Quote(Folder)).Append('\n');
        ServerLines(s);
        string asked = ShellWord.Quote(WorkingDirectory);
        s.Append("cd -- ").Append(asked).Append(" 2>/dev/null || { echo \"shards.sbatch: \"").Append(asked)
            .Append("\" (where the batch was asked from) is not on this node: running in $folder, where relative paths of the options are not found\" >&2; cd -- \"$folder\"; }\n");
        s.Append("exec \"${server[@]}\"");
        s.Append(' ').Append(ShellWord.Quote(Command));
        Words(s, RunArguments);
        if (!ThreadsPassedOn)
        {
            s.Append(" --threads ").Append(Cpus.ToString(CultureInfo.InvariantCulture));
        }

        // The submission plays only shards without a whole result, so a file left there is an unfinished one to replace.
        s.Append(" --shard \"$shard/").Append(Shards.ToString(CultureInfo.InvariantCulture)).Append("\" --results \"$folder/shard-$shard.jsonl\"");
        s.Append(Command == "run" ? " --force\n" : "\n");
        return s.ToString();
    }

    /// <summary>The text of <c>merge.sbatch</c>.</summary>
    public string MergeScript()
    {
        var s = Script(
            "The merge job: merges shard-0.jsonl ... shard-" + (Shards - 1).ToString(CultureInfo.InvariantCulture) + ".jsonl into the results file and prints the aggregate.",
            "Submitted by submit.sh, next to this file, to run when every task of the array has succeeded.");
        s.Append("folder=").Append(ShellWord.Quote(Folder)).Append('\n');
        s.Append("files=()\n");
        s.Append("for ((i = 0; i < ").Append(Shards.ToString(CultureInfo.InvariantCulture)).Append("; i++)); do files+=(\"$folder/shard-$i.jsonl\"); done\n");
        ServerLines(s);
        s.Append("exec \"${server[@]}\"");
        Words(s, MergeArguments ?? ["merge", "--out", Results, "--force"]); // the merge rebuilds the results from every shard
        s.Append(" \"${files[@]}\"\n");
        return s.ToString();
    }

    /// <summary>The text of <c>submit.sh</c>.</summary>
    public string SubmitScript()
    {
        var s = Script(
            "Submits the batch: a job array of the shards still to play, then the merge job after it.",
            "Rewritten, with the shards then still to play, each time the batch is asked for again.");
        s.Append("folder=").Append(ShellWord.Quote(Folder)).Append('\n');
        string shards = Shards.ToString(CultureInfo.InvariantCulture);
        string limits = (Partition is null ? string.Empty : " --partition=" + ShellWord.Quote(Partition))
            + (TimeLimit is null ? string.Empty : " --time=" + ShellWord.Quote(TimeLimit))
            + string.Concat((SbatchArguments ?? []).Select(a => " " + ShellWord.Quote(a)));
        string results = ShellWord.Quote(Results);
        if (ToPlay.Count > 0)
        {
            string array = ArraySpec.Format(ToPlay);
            s.Append("array=$(sbatch --parsable --job-name=urwpg-shards --array=").Append(array)
                .Append(" --cpus-per-task=").Append(Cpus.ToString(CultureInfo.InvariantCulture)).Append(limits)
                .Append(" --chdir=\"$folder\" --output=").Append(LogFolder).Append("/shard-%a.txt \"$folder/").Append(ShardScriptName).Append("\")\n");
            s.Append("array=${array%%;*}\n");
            s.Append("echo \"array job $array: shards ").Append(array).Append(" of ").Append(shards)
                .Append(", results in $folder/shard-I.jsonl, logs in $folder/").Append(LogFolder).Append("/shard-I.txt\"\n");
            s.Append("merge=$(sbatch --parsable --job-name=urwpg-merge --dependency=afterok:\"$array\" --kill-on-invalid-dep=yes")
                .Append(limits).Append(" --chdir=\"$folder\" --output=").Append(LogFolder).Append("/merge.txt \"$folder/").Append(MergeScriptName).Append("\")\n");
            s.Append("merge=${merge%%;*}\n");
            s.Append("echo \"merge job $merge: after array job $array succeeds, writes \"").Append(results).Append('\n');
        }
        else
        {
            s.Append("merge=$(sbatch --parsable --job-name=urwpg-merge").Append(limits)
                .Append(" --chdir=\"$folder\" --output=").Append(LogFolder).Append("/merge.txt \"$folder/").Append(MergeScriptName).Append("\")\n");
            s.Append("merge=${merge%%;*}\n");
            s.Append("echo \"no array job: all ").Append(shards).Append(" shards have their results\"\n");
            s.Append("echo \"merge job $merge: writes \"").Append(results).Append('\n');
        }

        return s.ToString();
    }

    private StringBuilder Script(string what, string how)
    {
        var s = new StringBuilder("#!/bin/bash\n");
        s.Append("# ").Append(what).Append('\n');
        s.Append("# Written by urwpgsim2d run --slurm (docs/batch.md). ").Append(how).Append('\n');
        s.Append("# The batch: run").Append(Comment(string.Join(' ', RunArguments.Select(ShellWord.Quote)))).Append('\n');
        s.Append("set -euo pipefail\n");
        return s;
    }

    // The setup file, then the server the job runs as the array "server": the defaults are the
    // server that wrote the script (dotnet on its DLL, or the program itself), each overridden by
    // its environment variable; a default dotnet host missing on the node gives way to the dotnet
    // on PATH (a module's, say).
    private void ServerLines(StringBuilder s)
    {
        if (Setup is not null)
        {
            string setup = ShellWord.Quote(Setup);
            s.Append("set +u # --slurm-setup: module scripts read unset variables\n");
            s.Append("source ").Append(setup).Append(" || { echo \"slurm setup \"").Append(setup).Append("\" failed\" >&2; exit 1; }\n");
            s.Append("set -u\n");
        }

        bool framework = Server.Count == 2;
        s.Append("dotnet=${").Append(DotnetVariable).Append(":-").Append(framework ? ShellWord.Quote(Server[0]) : "dotnet").Append("}\n");
        s.Append("[ -n \"${").Append(DotnetVariable).Append(":-}\" ] || command -v \"$dotnet\" >/dev/null || dotnet=dotnet\n");
        s.Append("server=${").Append(ServerVariable).Append(":-").Append(ShellWord.Quote(Server[^1])).Append("}\n");
        s.Append("if [[ $server == *.dll ]]; then server=(\"$dotnet\" \"$server\"); else server=(\"$server\"); fi\n");
    }

    private static void Words(StringBuilder s, IEnumerable<string> words)
    {
        foreach (string w in words)
        {
            s.Append(' ').Append(ShellWord.Quote(w));
        }
    }

    // One comment line: a line break in a quoted word would end the comment.
    private static string Comment(string text)
    {
        var s = new StringBuilder(text.Length + 1);
        s.Append(' ');
        foreach (char c in text)
        {
            s.Append(char.IsControl(c) ? '?' : c);
        }

        return s.ToString();
    }

    [GeneratedRegex(@"^[A-Za-z0-9_.\-]+(,[A-Za-z0-9_.\-]+)*$")]
    private static partial Regex Partitions();

    [GeneratedRegex(@"^([0-9]+|[0-9]+:[0-9]+|[0-9]+:[0-9]+:[0-9]+|[0-9]+-[0-9]+|[0-9]+-[0-9]+:[0-9]+|[0-9]+-[0-9]+:[0-9]+:[0-9]+|infinite|unlimited|INFINITE|UNLIMITED)$")]
    private static partial Regex TimeLimits();
}
