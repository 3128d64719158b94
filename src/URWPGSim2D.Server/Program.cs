using URWPGSim2D.Server.Cli;

namespace URWPGSim2D.Server;

/// <summary>The process entry point: hands the arguments and the console streams to <see cref="CliApp"/>.</summary>
internal static class Program
{
    /// <summary>Runs the command line and returns its exit code (see <see cref="ExitCodes"/>).</summary>
    /// <param name="args">The command-line arguments after the program name.</param>
    /// <returns>0 on success, 2 on bad input or arguments, 1 on an internal error.</returns>
    private static int Main(string[] args)
    {
        if (args.Length > 0 && args[0] == Hosting.CompilerProcess.Command)
        {
            return Hosting.CompilerProcess.Child(args.AsSpan(1)); // the server's strategy compiler, in a child process of its own
        }

        // Standard input is read as UTF-8 (a byte-order mark is honoured), whatever the locale says.
        using var stdin = new StreamReader(Console.OpenStandardInput(), new UTF8Encoding(encoderShouldEmitUTF8Identifier: false));
        return CliApp.Run(args, stdin, Console.Out, Console.Error);
    }
}
