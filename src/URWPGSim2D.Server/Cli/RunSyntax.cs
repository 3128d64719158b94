using System.CommandLine;
using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The declared options of <c>run</c>, in the order its usage names them: what the parser
/// recognises, the source of "did you mean" hints and of shell completion. <see cref="RunOptions"/>
/// checks their values.
/// </summary>
internal static class RunSyntax
{
    /// <summary><c>--help</c>, <c>-h</c>.</summary>
    public static Option<bool> Help { get; } = CliSyntax.Help();

    /// <summary><c>--list-items</c>.</summary>
    public static Option<bool> ListItems { get; } = CliSyntax.Flag("--list-items", "list the competition items and stop");

    /// <summary>The command with every option.</summary>
    public static Command Command { get; } = CliSyntax.Command(
        "run",
        "Play a match and print a summary.",
        [
            CliSyntax.Value("--item", "NAME", "the competition item (name or Chinese name)", CliCompletions.RunItems),
            CliSyntax.Value("--scenario", "FILE", "a scenario file (- for stdin)", CliCompletions.Paths),
            CliSyntax.Value("--crowd", "N", "a generated scene of N fish and balls"),
            CliSyntax.Value("--minutes", "10|5|3|1", "match length", CliCompletions.Fixed("10", "5", "3", "1")),
            CliSyntax.Value("--cycles", "N", "match length in cycles"),
            ListItems,
            CliSyntax.Value("--seed", "S", "the match's seed"),
            CliSyntax.Value("--noise", "on|off", "the noise of the fish's motion", CliCompletions.Fixed("on", "off")),
            CliSyntax.Repeated("--strategy", "TEAM=SPEC", "a team's strategy: built-in name, .dll, .cs file, folder or remote:PORT", CliCompletions.TeamStrategies),
            CliSyntax.Value("--remote-wait", "SECONDS", "how long to wait for remote teams"),
            CliSyntax.Value("--remote-host", "ADDR", "the address remote teams connect to"),
            CliSyntax.Repeated("--remote-token", "[TEAM=]TOKEN", "the token a remote team must present"),
            CliSyntax.Value("--strategy-timeout", "MS", "a strategy's CPU time per call"),
            CliSyntax.Value("--time-bank", "SECONDS", "each team's time bank for late calls"),
            .. HostOptions.Declare(),
            CliSyntax.Value("--trace", "FILE", "write the match's trace", CliCompletions.Paths),
            CliSyntax.Value("--svg", "FILE", "draw the last cycle as SVG", CliCompletions.Paths),
            CliSyntax.Value("--html", "FILE", "write the replay page", CliCompletions.Paths),
            CliSyntax.Flag("--force", "replace existing output files"),
            CliSyntax.Flag("--debug-draw", "record the strategies' drawings"),
            CliSyntax.Flag("--strategy-log", "record what the strategies print"),
            CliSyntax.Value("--threads", "P", "matches at once (batch) or threads of one match"),
            CliSyntax.Flag("--live", "play the match in the browser"),
            CliSyntax.Value("--port", "N", "the live view's port"),
            CliSyntax.Value("--host", "H", "the live view's address"),
            CliSyntax.Value("--speed", "X", "live speed, times real time"),
            CliSyntax.Flag("--paused", "start the live match paused"),
            CliSyntax.Value("--strategies", "DIR", "the folder of strategies the live view's control board offers", CliCompletions.Folders),
            CliSyntax.Value("--batch", "N", "play N matches"),
            CliSyntax.Value("--shard", "I/K", "play shard I of K of the batch"),
            CliSyntax.Value("--results", "FILE", "the batch's result file", CliCompletions.Paths),
            .. SlurmSyntax.Declare("DIR", "the batch"),
            Help,
        ]);
}
