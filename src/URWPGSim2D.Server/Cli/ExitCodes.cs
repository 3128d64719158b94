namespace URWPGSim2D.Server.Cli;

/// <summary>The process exit codes of the command line (documented in docs/cli.md).</summary>
internal static class ExitCodes
{
    /// <summary>The command ran and wrote its whole output.</summary>
    public const int Success = 0;

    /// <summary>An unexpected failure inside the program (a bug): one line on stderr, nothing on stdout.</summary>
    public const int InternalError = 1;

    /// <summary>Bad input data or bad arguments: one line on stderr, nothing on stdout.</summary>
    public const int BadInput = 2;
}
