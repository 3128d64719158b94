namespace URWPGSim2D.Server.Cli;

/// <summary>
/// One sub-command of the program (<c>run</c>, <c>collide</c>, <c>tournament</c>, ...).
/// A command lives in its own file and is registered once, in <see cref="CliApp"/>.
/// </summary>
internal interface ICliCommand
{
    /// <summary>The word that selects the command, e.g. <c>collide</c>.</summary>
    string Name { get; }

    /// <summary>The command and its arguments as shown in usage lines, e.g. <c>collide FILE</c>.</summary>
    string Synopsis { get; }

    /// <summary>A one-line description for the program's <c>--help</c>.</summary>
    string Summary { get; }

    /// <summary>
    /// The command's options and arguments, declared once (<see cref="CliSyntax"/>): what the parser
    /// recognises, what "did you mean" hints and shell completion offer.
    /// </summary>
    Command Syntax { get; }

    /// <summary>
    /// Runs the command. Bad arguments throw <see cref="CliUsageException"/>, bad input throws
    /// <see cref="InputException"/>; in both cases nothing may have been written to stdout.
    /// </summary>
    /// <param name="words">The words after the command name, as the parser classified them against <see cref="Syntax"/>.</param>
    /// <param name="console">The streams to use.</param>
    /// <returns>The exit code (see <see cref="ExitCodes"/>).</returns>
    int Run(IReadOnlyList<CommandLineWord> words, CliConsole console);
}
