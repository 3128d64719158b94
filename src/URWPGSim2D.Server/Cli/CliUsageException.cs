using System;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// Bad command-line arguments (unknown command, missing or extra argument, unknown option):
/// reported as the single stderr line <c>MESSAGE. Usage: SYNOPSIS</c>, exit code 2.
/// </summary>
internal sealed class CliUsageException : Exception
{
    /// <summary>Creates the error.</summary>
    /// <param name="message">What is wrong with the arguments, one line.</param>
    /// <param name="usage">The synopsis to show, e.g. <c>URWPGSim2D.Server collide FILE</c>.</param>
    public CliUsageException(string message, string usage)
        : base(message)
    {
        Usage = usage;
    }

    /// <summary>The synopsis shown after the message.</summary>
    public string Usage { get; }

    /// <summary>The line written to stderr.</summary>
    public string Line => $"{Message}. Usage: {Usage}";
}
