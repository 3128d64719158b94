namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The declared options of <c>tournament</c>, written once in its usage line: what the parser
/// recognises, what <c>--help</c> shows, the source of "did you mean" hints and of shell completion.
/// <see cref="TournamentOptions"/> checks their values.
/// </summary>
internal static class TournamentSyntax
{
    /// <summary><c>--help</c>, <c>-h</c>.</summary>
    public static Option<bool> Help { get; } = CliSyntax.Help();

    /// <summary><c>--merge FILE...</c>: takes every word after it.</summary>
    public static Option<string[]> Merge { get; } = MergeOption();

    /// <summary>The command's usage line, which declares every option but <c>--help</c>.</summary>
    public static UsageLine Usage { get; } = new(
    [
        CliSyntax.Value("--item", "ITEM", "the item the entrants play (name or Chinese name)", CliCompletions.TournamentItems),
        UsageLine.Repeated(UsageLine.Required(UsageLine.OneOf(
            CliSyntax.Repeated("--entrant", "NAME=SPEC", "an entrant: its name and its strategy", CliCompletions.Entrants),
            CliSyntax.Value("--entrants-dir", "DIR", "a folder whose every sub-folder, .cs file and DLL is an entrant named after it", CliCompletions.Folders)))),
        UsageLine.Optional(CliSyntax.Value("--seeds", "N", "seeds each pairing plays")),
        UsageLine.Optional(CliSyntax.Value("--seed", "S", "the first seed")),
        UsageLine.Optional(UsageLine.OneOf(
            CliSyntax.Value("--minutes", "10|5|3|1", "match length", CliCompletions.Fixed("10", "5", "3", "1")),
            CliSyntax.Value("--cycles", "N", "match length in cycles"))),
        UsageLine.Optional(CliSyntax.Value("--strategy-timeout", "MS", "a strategy's CPU time per call")),
        .. HostOptions.Declare(),
        UsageLine.Optional(CliSyntax.Value("--threads", "P", "matches at once")),
        UsageLine.Optional(CliSyntax.Value("--remote-wait", "SECONDS", "how long a match waits for a remote entrant's client")),
        UsageLine.Optional(CliSyntax.Value("--remote-host", "ADDR", "the address remote entrants' clients connect to")),
        UsageLine.Optional(CliSyntax.Repeated("--remote-token", "[NAME=]TOKEN", "the token a remote entrant's client must present")),
        UsageLine.Optional(CliSyntax.Flag("--replays", "write a replay page of every match")),
        UsageLine.Optional(
            CliSyntax.Flag("--live", "play the matches one after another in the live page (a projector view)"),
            UsageLine.Optional(CliSyntax.Value("--port", "N", "the live page's port")),
            UsageLine.Optional(CliSyntax.Value("--host", "H", "the live page's address")),
            UsageLine.Optional(CliSyntax.Value("--speed", "X", "live speed, times real time"))),
        UsageLine.Optional(
            CliSyntax.Value("--format", "round-robin|groups-knockout", "every pair (the default), or groups then a knockout", CliCompletions.Fixed("round-robin", "groups-knockout")),
            UsageLine.Optional(CliSyntax.Value("--groups", "G", "groups of the group stage")),
            UsageLine.Optional(CliSyntax.Value("--advance", "K", "entrants of each group into the knockout")),
            UsageLine.Optional(CliSyntax.Value("--final-seeds", "F", "seeds of the final")),
            UsageLine.Optional(CliSyntax.Value("--seeding", "NAME,...", "the entrants' seeding order for the groups"))),
        UsageLine.Required(UsageLine.OneOf(
            CliSyntax.Value("--out", "DIR", "the folder of the results, standings and report", CliCompletions.Folders),
            CliSyntax.Flag("--check", "check each entrant: loads, one minute against idle, faults, slowest call"))),
        SlurmSyntax.Declare("SDIR", "the tournament"),
        UsageLine.Optional(
            CliSyntax.Value("--shard", "I/K", "play shard I of K"),
            CliSyntax.Value("--results", "FILE", "the shard's result file", CliCompletions.Paths)),
        UsageLine.Optional(Merge),
    ]);

    /// <summary>The command with every option of <see cref="Usage"/> and <see cref="Help"/>.</summary>
    public static Command Command { get; } = CliSyntax.Command("tournament", "Rank strategies.", Usage, Help);

    private static Option<string[]> MergeOption()
    {
        var merge = CliSyntax.Repeated("--merge", "FILE", "gather these shard result files", CliCompletions.Paths);
        merge.Arity = ArgumentArity.OneOrMore;
        merge.AllowMultipleArgumentsPerToken = true;
        return merge;
    }
}
