namespace URWPGSim2D.Server.Cli;

/// <summary>
/// Bad command-line arguments (unknown command, missing or extra argument, unknown option):
/// reported as the single stderr line <c>MESSAGE. Usage: SYNOPSIS</c>, exit code 2; a typo with
/// a near name is the shorter line <c>MESSAGE; did you mean NAME?</c>.
/// </summary>
internal sealed class CliUsageException : Exception
{
    /// <summary>Creates the error.</summary>
    /// <param name="message">What is wrong with the arguments, one line.</param>
    /// <param name="usage">The synopsis to show, e.g. <c>urwpgsim2d collide FILE</c>; null for none.</param>
    public CliUsageException(string message, string? usage)
        : base(message)
    {
        Usage = usage;
    }

    /// <summary>The synopsis shown after the message, or null.</summary>
    public string? Usage { get; }

    /// <summary>The line written to stderr.</summary>
    public string Line => Usage is null ? Message : $"{Message}. Usage: {Usage}";

    /// <summary>
    /// An unknown option of <paramref name="command"/>: with the nearest of the options its
    /// <paramref name="syntax"/> declares (<see cref="Suggestion"/>), <c>COMMAND: unknown option
    /// "X"; did you mean --Y?</c>; without one, the message and the usage.
    /// </summary>
    /// <param name="command">The command's name, e.g. <c>run</c>.</param>
    /// <param name="option">The option as given.</param>
    /// <param name="syntax">The command's declared syntax, the source of the option names.</param>
    /// <param name="usage">The command's usage.</param>
    public static CliUsageException UnknownOption(string command, string option, Command syntax, string usage)
    {
        ArgumentNullException.ThrowIfNull(syntax);
        string message = $"{command}: unknown option {MessageText.Quote(option)}";
        return Suggestion.Nearest(option, CliSyntax.LongNames(syntax)) is { } near
            ? new CliUsageException($"{message}; did you mean {near}?", null)
            : new CliUsageException(message, usage);
    }
}
