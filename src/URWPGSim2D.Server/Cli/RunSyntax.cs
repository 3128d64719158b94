namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The declared options of <c>run</c>, written once in its usage line: what the parser recognises,
/// what <c>--help</c> shows, the source of "did you mean" hints and of shell completion.
/// <see cref="RunOptions"/> checks their values.
/// </summary>
internal static class RunSyntax
{
    /// <summary><c>--help</c>, <c>-h</c>.</summary>
    public static Option<bool> Help { get; } = CliSyntax.Help();

    /// <summary><c>--list-items</c>.</summary>
    public static Option<bool> ListItems { get; } = CliSyntax.Flag("--list-items", "list the competition items and stop");

    /// <summary>The command's usage line, which declares every option but <c>--help</c>.</summary>
    public static UsageLine Usage { get; } = new(
    [
        UsageLine.Optional(UsageLine.OneOf(
            CliSyntax.Value("--item", "NAME", "the competition item (name or Chinese name)", CliCompletions.RunItems),
            CliSyntax.Value("--scenario", "FILE", "a scenario file (- for stdin)", CliCompletions.Paths),
            CliSyntax.Value("--crowd", "N", "a generated scene of N fish and balls"))),
        UsageLine.Optional(UsageLine.OneOf(
            CliSyntax.Value("--minutes", "10|5|3|1", "match length", CliCompletions.Fixed("10", "5", "3", "1")),
            CliSyntax.Value("--cycles", "N", "match length in cycles"))),
        UsageLine.Optional(ListItems),
        UsageLine.Optional(CliSyntax.Value("--seed", "S", "the match's seed")),
        UsageLine.Optional(CliSyntax.Value("--noise", "on|off", "the noise of the fish's motion", CliCompletions.Fixed("on", "off"))),
        UsageLine.Optional(CliSyntax.Repeated("--strategy", "TEAM=SPEC|TEAM=remote:PORT", "a team's strategy: built-in name, .dll, .cs file, folder or remote:PORT", CliCompletions.TeamStrategies)),
        UsageLine.Optional(CliSyntax.Value("--remote-wait", "SECONDS", "how long to wait for remote teams")),
        UsageLine.Optional(CliSyntax.Value("--remote-host", "ADDR", "the address remote teams connect to")),
        UsageLine.Optional(CliSyntax.Repeated("--remote-token", "[TEAM=]TOKEN", "the token a remote team must present")),
        UsageLine.Optional(CliSyntax.Value("--strategy-timeout", "MS", "a strategy's CPU time per call")),
        UsageLine.Optional(CliSyntax.Value("--time-bank", "SECONDS", "each team's time bank for late calls")),
        .. HostOptions.Declare(),
        UsageLine.Optional(CliSyntax.Value("--trace", "FILE", "write the match's trace", CliCompletions.Paths)),
        UsageLine.Optional(CliSyntax.Value("--svg", "FILE", "draw the last cycle as SVG", CliCompletions.Paths)),
        UsageLine.Optional(CliSyntax.Value("--html", "FILE", "write the replay page", CliCompletions.Paths)),
        UsageLine.Optional(CliSyntax.Flag("--force", "replace existing output files")),
        UsageLine.Optional(CliSyntax.Flag("--debug-draw", "record the strategies' drawings")),
        UsageLine.Optional(CliSyntax.Flag("--strategy-log", "record what the strategies print")),
        UsageLine.Optional(CliSyntax.Value("--threads", "P", "matches at once (batch) or threads of one match")),
        UsageLine.Optional(
            CliSyntax.Flag("--live", "play the match in the browser"),
            UsageLine.Optional(CliSyntax.Value("--port", "N", "the live view's port")),
            UsageLine.Optional(CliSyntax.Value("--host", "H", "the live view's address")),
            UsageLine.Optional(CliSyntax.Value("--speed", "X", "live speed, times real time")),
            UsageLine.Optional(CliSyntax.Flag("--paused", "start the live match paused")),
            UsageLine.Optional(CliSyntax.Value("--strategies", "DIR", "the folder of strategies the live view's control board offers", CliCompletions.Folders))),
        UsageLine.Optional(
            CliSyntax.Value("--batch", "N", "play N matches"),
            UsageLine.Optional(CliSyntax.Value("--shard", "I/K", "play shard I of K of the batch")),
            UsageLine.Optional(CliSyntax.Value("--results", "FILE", "the batch's result file", CliCompletions.Paths))),
        SlurmSyntax.Declare("DIR", "the batch"),
    ]);

    /// <summary>The command with every option of <see cref="Usage"/> and <see cref="Help"/>.</summary>
    public static Command Command { get; } = CliSyntax.Command("run", "Play a match and print a summary.", Usage, Help);
}
