using System;
using System.IO;
using System.Linq;
using System.Text;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The command line, callable in-process: routes <c>args[0]</c> to a registered
/// <see cref="ICliCommand"/>, prints help, and turns every failure into one stderr line
/// and an exit code. <c>Program.Main</c> only forwards to <see cref="Run"/>.
/// </summary>
internal static class CliApp
{
    /// <summary>The program name shown in usage text.</summary>
    public const string ProgramName = "URWPGSim2D.Server";

    /// <summary>Every command, in the order <c>--help</c> lists them. Register new commands here.</summary>
    private static readonly ICliCommand[] Commands =
    [
        new CollideCommand(),
    ];

    /// <summary>The one-line synopsis of the whole program, used in usage errors.</summary>
    public static string Synopsis =>
        $"{ProgramName} <command> [arguments] (commands: {string.Join(", ", Commands.Select(c => c.Name))}; --help for details)";

    /// <summary>Runs the command line.</summary>
    /// <param name="args">The arguments after the program name.</param>
    /// <param name="stdin">Standard input.</param>
    /// <param name="stdout">Standard output; written only when a command succeeds.</param>
    /// <param name="stderr">Standard error; usage text or a single error line.</param>
    /// <returns>The exit code: 0 success, 1 internal error, 2 bad input or arguments.</returns>
    public static int Run(string[] args, TextReader stdin, TextWriter stdout, TextWriter stderr)
    {
        ArgumentNullException.ThrowIfNull(args);
        var console = new CliConsole(stdin, stdout, stderr);
        try
        {
            if (args.Length == 0)
            {
                return RunWithoutArguments(console);
            }

            if (IsHelp(args[0]))
            {
                stdout.Write(HelpText());
                return ExitCodes.Success;
            }

            ICliCommand command = Find(args[0])
                ?? throw new CliUsageException($"unknown command \"{args[0]}\"", Synopsis);
            return command.Run(args.AsSpan(1), console);
        }
        catch (CliUsageException ex)
        {
            stderr.WriteLine(ex.Line);
            return ExitCodes.BadInput;
        }
        catch (CliInputException ex)
        {
            stderr.WriteLine(ex.Line);
            return ExitCodes.BadInput;
        }
        catch (Exception ex)
        {
            // A bug, not bad input: still one line and no stack trace, but a distinct exit code.
            stderr.WriteLine($"internal error: {ex.GetType().Name}: {OneLine(ex.Message)}");
            return ExitCodes.InternalError;
        }
    }

    /// <summary>True for the arguments that ask for help: <c>--help</c> and <c>-h</c>.</summary>
    /// <param name="argument">One argument.</param>
    /// <returns>Whether it asks for help.</returns>
    public static bool IsHelp(string argument) => argument is "--help" or "-h";

    /// <summary>The program's help: every command's synopsis and summary, and the exit codes.</summary>
    /// <returns>Multi-line text ending in a newline.</returns>
    public static string HelpText()
    {
        int width = Commands.Max(c => c.Synopsis.Length);
        var text = new StringBuilder();
        text.Append(ProgramName).Append(": command-line front end of the URWPGSim2D.Collision library.\n\n");
        text.Append("Usage:\n");
        foreach (var command in Commands)
        {
            text.Append("  ").Append(ProgramName).Append(' ').Append(command.Synopsis.PadRight(width))
                .Append("  ").Append(command.Summary).Append('\n');
        }

        text.Append("  ").Append(ProgramName).Append(' ').Append("--help".PadRight(width)).Append("  Show this help.\n\n");
        text.Append("FILE may be - to read standard input. '").Append(ProgramName)
            .Append(" COMMAND --help' describes one command.\n");
        text.Append("Exit codes: 0 success; 2 bad input or arguments (one line on stderr, nothing on stdout); 1 internal error.\n");
        text.Append("Formats: docs/cli.md.\n");
        return text.ToString();
    }

    /// <summary>
    /// What an empty command line does. This is the single place where the default command will
    /// be wired: the <c>run</c> command (a simulated match) becomes the default once it exists.
    /// Until then an empty command line prints the help to stderr and fails.
    /// </summary>
    private static int RunWithoutArguments(CliConsole console)
    {
        console.Error.Write(HelpText());
        return ExitCodes.BadInput;
    }

    private static ICliCommand? Find(string name) => Array.Find(Commands, c => c.Name == name);

    private static string OneLine(string text) => text.ReplaceLineEndings(" ");
}
