namespace URWPGSim2D.Server.Cli;

/// <summary>The single FILE argument of <c>collide</c> and <c>shapes</c> (and the FILE of <c>render</c>): a path, or <c>-</c> for stdin.</summary>
internal static class FileArgument
{
    /// <summary>Checks that the arguments are exactly one FILE.</summary>
    /// <param name="command">The command name, the prefix of every message.</param>
    /// <param name="words">The words after the command name.</param>
    /// <param name="syntax">The command's declared syntax (for "did you mean").</param>
    /// <param name="usage">The usage line shown after a message.</param>
    /// <returns>The file path, or <c>-</c>.</returns>
    /// <exception cref="CliUsageException">Not exactly one argument, an empty one, or an option.</exception>
    public static string Parse(string command, IReadOnlyList<CommandLineWord> words, Command syntax, string usage)
    {
        if (words.Count != 1)
        {
            throw new CliUsageException($"{command}: expected one FILE argument (- for stdin), got {words.Count}", usage);
        }

        return Check(command, words[0].Text, syntax, usage);
    }

    /// <summary>The declared positional FILE of a command: a path, or <c>-</c> for stdin.</summary>
    /// <param name="description">What the file holds.</param>
    public static Argument<string[]> Declare(string description) =>
        CliSyntax.Positional("FILE", description, CliCompletions.Paths);

    /// <summary>Checks one FILE argument: not empty, and not an option (a leading <c>-</c> other than <c>-</c> itself).</summary>
    /// <param name="command">The command name, the prefix of every message.</param>
    /// <param name="file">The argument.</param>
    /// <param name="syntax">The command's declared syntax (for "did you mean").</param>
    /// <param name="usage">The usage line shown after a message.</param>
    /// <returns>The argument.</returns>
    /// <exception cref="CliUsageException">The argument is empty or looks like an unknown option.</exception>
    public static string Check(string command, string file, Command syntax, string usage)
    {
        if (file.Length == 0)
        {
            throw new CliUsageException($"{command}: FILE is empty", usage);
        }

        if (file.StartsWith('-') && file != InputText.StandardInput)
        {
            throw CliUsageException.UnknownOption(command, file, syntax, usage);
        }

        return file;
    }
}
