namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The command line, callable in-process: parses the arguments with System.CommandLine against
/// the commands' declared syntax (<see cref="ICliCommand.Syntax"/>), answers shell completion
/// (<see cref="ShellCompletion"/>), hands the chosen <see cref="ICliCommand"/> its classified words,
/// prints help, and turns every failure into one stderr line and an exit code. <c>Program.Main</c> only forwards to <see cref="Run(string[], TextReader, TextWriter, TextWriter)"/>.
/// </summary>
internal sealed class CliApp
{
    /// <summary>The program name shown in usage text.</summary>
    public const string ProgramName = "urwpgsim2d";

    private readonly ICliCommand[] _commands;

    /// <summary>Creates a command line over the given commands.</summary>
    /// <param name="commands">The commands, in the order <c>--help</c> lists them; at least one; each in one command line only.</param>
    public CliApp(IEnumerable<ICliCommand> commands)
    {
        _commands = [.. commands];
        if (_commands.Length == 0)
        {
            throw new ArgumentException("at least one command is needed", nameof(commands));
        }

        Root = new RootCommand("The URWPGSim2D match server.");
        Root.Options.Clear(); // no --version; --help is answered before parsing
        Root.Options.Add(CliSyntax.Help());
        foreach (var command in _commands)
        {
            Root.Subcommands.Add(command.Syntax);
        }
    }

    /// <summary>The declared syntax of the whole program: every command's options and arguments.</summary>
    public RootCommand Root { get; }

    /// <summary>Every command of the program, in the order <c>--help</c> lists them. Register new commands here.</summary>
    public static IReadOnlyList<ICliCommand> DefaultCommands { get; } =
    [
        new RunCommand(),
        new CollideCommand(),
        new QueryCommand(),
        new ShapesCommand(),
        new RenderCommand(),
        new MergeCommand(),
        new ViewCommand(),
        new TournamentCommand(),
        new HostCommand(),
        new ConnectCommand(),
        new InspectDllCommand(),
        new LadderCommand(),
        new CompletionCommand(),
    ];

    /// <summary>The program's command line: <see cref="DefaultCommands"/>.</summary>
    public static CliApp Default { get; } = new(DefaultCommands);

    /// <summary>The one-line synopsis of the whole program, used in usage errors.</summary>
    public string Synopsis =>
        $"{ProgramName} <command> [arguments] (commands: {string.Join(", ", _commands.Select(c => c.Name))}; --help for details)";

    /// <summary>Runs the program's command line (<see cref="DefaultCommands"/>).</summary>
    /// <param name="args">The arguments after the program name.</param>
    /// <param name="stdin">Standard input.</param>
    /// <param name="stdout">Standard output; written only when a command succeeds.</param>
    /// <param name="stderr">Standard error; usage text or a single error line.</param>
    /// <returns>The exit code: 0 success, 1 internal error, 2 bad input or arguments.</returns>
    public static int Run(string[] args, TextReader stdin, TextWriter stdout, TextWriter stderr) =>
        Default.Run(args, new CliConsole(stdin, stdout, stderr));

    /// <summary>True for the arguments that ask for help: <c>--help</c> and <c>-h</c>.</summary>
    /// <param name="argument">One argument.</param>
    /// <returns>Whether it asks for help.</returns>
    public static bool IsHelp(string argument) => argument is "--help" or "-h";

    /// <summary>The words of one command's arguments, parsed against its declared syntax.</summary>
    /// <param name="command">The command's name.</param>
    /// <param name="arguments">The arguments after it.</param>
    /// <returns>The classified words.</returns>
    public IReadOnlyList<CommandLineWord> Words(string command, ReadOnlySpan<string> arguments) =>
        CommandLineWords.Of(Root.Parse([command, .. arguments], CliSyntax.Parser));

    /// <summary>Runs a command line.</summary>
    /// <param name="args">The arguments after the program name.</param>
    /// <param name="console">The streams to use.</param>
    /// <returns>The exit code: 0 success, 1 internal error, 2 bad input or arguments.</returns>
    public int Run(string[] args, CliConsole console)
    {
        ArgumentNullException.ThrowIfNull(args);
        ArgumentNullException.ThrowIfNull(console);
        try
        {
            if (args.Length == 0)
            {
                return RunWithoutArguments(console);
            }

            if (IsHelp(args[0]))
            {
                console.Out.Write(HelpText());
                return ExitCodes.Success;
            }

            if (ShellCompletion.IsRequest(args))
            {
                return ShellCompletion.Answer(Root, args, console);
            }

            ParseResult parse = Root.Parse(args, CliSyntax.Parser);
            ICliCommand command = Array.Find(_commands, c => Chose(parse.CommandResult, c.Syntax)) ?? throw UnknownCommand(args[0]);
            return command.Run(CommandLineWords.Of(parse), console);
        }
        catch (CliUsageException ex)
        {
            console.ErrorLine(ex.Line);
            return ExitCodes.BadInput;
        }
        catch (InputException ex)
        {
            console.ErrorLine(ex.Line);
            return ExitCodes.BadInput;
        }
        catch (Exception ex)
        {
            // A bug, not bad input: still one line and no stack trace, but a distinct exit code.
            console.ErrorLine($"internal error: {ex.GetType().Name}: {ex.Message.ReplaceLineEndings(" ")}");
            return ExitCodes.InternalError;
        }
    }

    // Whether the parse chose the command or one of its sub-commands (ladder serve).
    private static bool Chose(System.CommandLine.Parsing.CommandResult result, Command command)
    {
        for (System.CommandLine.Parsing.SymbolResult? r = result; r is not null; r = r.Parent)
        {
            if (r is System.CommandLine.Parsing.CommandResult c && c.Command == command)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>The program's help: every command's synopsis and summary, and the exit codes.</summary>
    /// <returns>Multi-line text ending in a newline.</returns>
    public string HelpText()
    {
        int width = Math.Max(_commands.Max(c => c.Synopsis.Length), "--help".Length);
        var text = new StringBuilder();
        text.Append(ProgramName).Append(": command-line front end of the URWPGSim2D.Collision library.\n\n");
        text.Append("Usage:\n");
        foreach (var command in _commands)
        {
            Line(command.Synopsis, command.Summary);
        }

        Line("--help", "Show this help.");
        text.Append('\n');
        text.Append("FILE may be - to read standard input. '").Append(ProgramName)
            .Append(" COMMAND --help' describes one command.\n");
        text.Append("Exit codes: 0 success; 2 bad input or arguments (one line on stderr, nothing on stdout); 1 internal error.\n");
        text.Append("Formats: docs/cli.md.\n");
        return text.ToString();

        void Line(string synopsis, string summary) =>
            text.Append("  ").Append(ProgramName).Append(' ').Append(synopsis.PadRight(width)).Append("  ").Append(summary).Append('\n');
    }

    // An unknown command: with the nearest command when one is near ("rn": run), else the synopsis.
    private CliUsageException UnknownCommand(string name)
    {
        string message = $"unknown command {MessageText.Quote(name)}";
        return Suggestion.Nearest(name, _commands.Select(c => c.Name)) is { } near
            ? new CliUsageException($"{message}; did you mean {near}?", null)
            : new CliUsageException(message, Synopsis);
    }

    /// <summary>The arguments of the first match a user sees, the program run with none: ball-grab, demo against demo, seed 6 (a match with a goal, 0:3).</summary>
    private static readonly string[] FirstMatch = ["--seed", "6"];

    /// <summary>
    /// What an empty command line does: the <c>run</c> command with <see cref="FirstMatch"/>. A command
    /// line without a <c>run</c> command prints the help to stderr and fails.
    /// </summary>
    private int RunWithoutArguments(CliConsole console)
    {
        ICliCommand? run = Array.Find(_commands, c => c.Name == "run");
        if (run is null)
        {
            console.Error.Write(HelpText());
            return ExitCodes.BadInput;
        }

        return run.Run(Words("run", FirstMatch), console);
    }
}
