using System;
using URWPGSim2D.Server.Json;

namespace URWPGSim2D.Server.Cli;

/// <summary>The single FILE argument of <c>collide</c> and <c>shapes</c> (and the FILE of <c>render</c>): a path, or <c>-</c> for stdin.</summary>
internal static class FileArgument
{
    /// <summary>Checks that the arguments are exactly one FILE.</summary>
    /// <param name="command">The command name, the prefix of every message.</param>
    /// <param name="arguments">The arguments after the command name.</param>
    /// <param name="usage">The usage line shown after a message.</param>
    /// <returns>The file path, or <c>-</c>.</returns>
    /// <exception cref="CliUsageException">Not exactly one argument, an empty one, or an option.</exception>
    public static string Parse(string command, ReadOnlySpan<string> arguments, string usage)
    {
        if (arguments.Length != 1)
        {
            throw new CliUsageException($"{command}: expected one FILE argument (- for stdin), got {arguments.Length}", usage);
        }

        return Check(command, arguments[0], usage);
    }

    /// <summary>Checks one FILE argument: not empty, and not an option (a leading <c>-</c> other than <c>-</c> itself).</summary>
    /// <param name="command">The command name, the prefix of every message.</param>
    /// <param name="file">The argument.</param>
    /// <param name="usage">The usage line shown after a message.</param>
    /// <returns>The argument.</returns>
    /// <exception cref="CliUsageException">The argument is empty or looks like an unknown option.</exception>
    public static string Check(string command, string file, string usage)
    {
        if (file.Length == 0)
        {
            throw new CliUsageException($"{command}: FILE is empty", usage);
        }

        if (file.StartsWith('-') && file != InputText.StandardInput)
        {
            throw CliUsageException.UnknownOption(command, file, usage);
        }

        return file;
    }
}
