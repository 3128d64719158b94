using System.CommandLine;
using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The declared options of <c>tournament</c>, in the order its usage names them: what the parser
/// recognises, the source of "did you mean" hints and of shell completion.
/// <see cref="TournamentOptions"/> checks their values.
/// </summary>
internal static class TournamentSyntax
{
    /// <summary><c>--help</c>, <c>-h</c>.</summary>
    public static Option<bool> Help { get; } = CliSyntax.Help();

    /// <summary><c>--merge FILE...</c>: takes every word after it.</summary>
    public static Option<string[]> Merge { get; } = MergeOption();

    /// <summary>The command with every option.</summary>
    public static Command Command { get; } = CliSyntax.Command(
        "tournament",
        "Rank strategies.",
        [
            CliSyntax.Value("--item", "ITEM", "the item the entrants play (name or Chinese name)", CliCompletions.TournamentItems),
            CliSyntax.Repeated("--entrant", "NAME=SPEC", "an entrant: its name and its strategy", CliCompletions.Entrants),
            CliSyntax.Value("--entrants-dir", "DIR", "a folder whose every sub-folder, .cs file and DLL is an entrant named after it", CliCompletions.Folders),
            CliSyntax.Value("--seeds", "N", "seeds each pairing plays"),
            CliSyntax.Value("--seed", "S", "the first seed"),
            CliSyntax.Value("--minutes", "10|5|3|1", "match length", CliCompletions.Fixed("10", "5", "3", "1")),
            CliSyntax.Value("--cycles", "N", "match length in cycles"),
            CliSyntax.Value("--strategy-timeout", "MS", "a strategy's CPU time per call"),
            .. HostOptions.Declare(),
            CliSyntax.Value("--threads", "P", "matches at once"),
            CliSyntax.Flag("--replays", "write a replay page of every match"),
            CliSyntax.Flag("--check", "check each entrant: loads, one minute against idle, faults, slowest call"),
            CliSyntax.Value("--format", "round-robin|groups-knockout", "every pair (the default), or groups then a knockout", CliCompletions.Fixed("round-robin", "groups-knockout")),
            CliSyntax.Value("--groups", "G", "groups of the group stage"),
            CliSyntax.Value("--advance", "K", "entrants of each group into the knockout"),
            CliSyntax.Value("--final-seeds", "F", "seeds of the final"),
            CliSyntax.Value("--seeding", "NAME,...", "the entrants' seeding order for the groups"),
            CliSyntax.Value("--out", "DIR", "the folder of the results, standings and report", CliCompletions.Folders),
            .. SlurmSyntax.Declare("SDIR", "the tournament"),
            CliSyntax.Value("--shard", "I/K", "play shard I of K"),
            CliSyntax.Value("--results", "FILE", "the shard's result file", CliCompletions.Paths),
            Merge,
            Help,
        ]);

    private static Option<string[]> MergeOption()
    {
        var merge = CliSyntax.Repeated("--merge", "FILE", "gather these shard result files", CliCompletions.Paths);
        merge.Arity = ArgumentArity.OneOrMore;
        merge.AllowMultipleArgumentsPerToken = true;
        return merge;
    }
}
