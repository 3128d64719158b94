using System;
using URWPGSim2D.Server.Cli;

namespace URWPGSim2D.Server;

/// <summary>The process entry point: hands the arguments and the console streams to <see cref="CliApp"/>.</summary>
internal static class Program
{
    /// <summary>Runs the command line and returns its exit code (see <see cref="ExitCodes"/>).</summary>
    /// <param name="args">The command-line arguments after the program name.</param>
    /// <returns>0 on success, 2 on bad input or arguments, 1 on an internal error.</returns>
    private static int Main(string[] args) => CliApp.Run(args, Console.In, Console.Out, Console.Error);
}
