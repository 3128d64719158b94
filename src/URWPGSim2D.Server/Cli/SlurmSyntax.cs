using System.Collections.Frozen;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The declared options of a Slurm job array, the same for <c>run --batch</c> and
/// <c>tournament</c> (docs/batch.md, "On a Slurm cluster"): <c>--slurm</c>, <c>--shards</c>,
/// <c>--partition</c>, <c>--time</c>, <c>--sbatch-arg</c>, <c>--slurm-setup</c>, <c>--submit</c>.
/// </summary>
internal static class SlurmSyntax
{
    // The options' names, from their declarations.
    private static readonly FrozenSet<string> Names =
        Declare("DIR", "a batch").Symbols.OfType<Option>().Select(o => o.Name).ToFrozenSet(StringComparer.Ordinal);

    /// <summary>Whether <paramref name="name"/> is one of these options.</summary>
    /// <param name="name">An option's name.</param>
    public static bool Is(string name) => Names.Contains(name);

    /// <summary>The options' declarations in a usage line, new for each command that takes them: <c>[--slurm DIR [--shards K] …]</c>.</summary>
    /// <param name="folder">The name of <c>--slurm</c>'s folder in the command's usage, e.g. <c>DIR</c>.</param>
    /// <param name="what">What the jobs play, e.g. <c>the batch</c>.</param>
    public static UsageLine.Term Declare(string folder, string what) => UsageLine.Optional(
        CliSyntax.Value("--slurm", folder, $"write a Slurm job array for {what}", CliCompletions.Folders),
        UsageLine.Optional(CliSyntax.Value("--shards", "K", "array tasks of the Slurm jobs")),
        UsageLine.Optional(CliSyntax.Value("--partition", "P", "the Slurm partition")),
        UsageLine.Optional(CliSyntax.Value("--time", "T", "the Slurm time limit")),
        UsageLine.Optional(CliSyntax.Repeated("--sbatch-arg", "ARG", "one more sbatch option")),
        UsageLine.Optional(CliSyntax.Value("--slurm-setup", "FILE", "a bash file the jobs source first", CliCompletions.Paths)),
        UsageLine.Optional(CliSyntax.Flag("--submit", "submit the written Slurm jobs")));
}
