namespace URWPGSim2D.Server.Cli;

/// <summary>
/// A command that reads one JSON document and writes its answer: <c>COMMAND FILE</c> (<c>-</c> for
/// stdin), or <c>COMMAND --help</c>. The whole input is read and validated before anything is
/// written: on bad input stdout stays empty. <c>collide</c>, <c>query</c> and <c>shapes</c>.
/// </summary>
internal abstract class JsonFileCommand : ICliCommand
{
    private readonly Option<bool> _help = CliSyntax.Help();
    private readonly UsageLine _line;

    /// <summary>Declares the command.</summary>
    /// <param name="name">Its name.</param>
    /// <param name="summary">Its line in the program's help.</param>
    /// <param name="file">What FILE holds, e.g. <c>pairs of shapes (JSON), - for stdin</c>.</param>
    protected JsonFileCommand(string name, string summary, string file)
    {
        Name = name;
        Summary = summary;
        _line = new UsageLine(FileArgument.Declare(file));
        Syntax = CliSyntax.Command(name, file, _line, _help);
    }

    /// <inheritdoc />
    public string Name { get; }

    /// <inheritdoc />
    public string Synopsis => $"{Name} {_line.Text}";

    /// <inheritdoc />
    public string Summary { get; }

    /// <inheritdoc />
    public Command Syntax { get; }

    /// <summary>The usage shown after a usage error and at the top of the help.</summary>
    protected string Usage => $"{CliApp.ProgramName} {Synopsis}";

    /// <inheritdoc />
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (words.Count == 1 && words[0].Option == _help)
        {
            console.Out.Write(HelpText());
            return ExitCodes.Success;
        }

        string file = FileArgument.Parse(Name, words, Syntax, Usage);
        console.Out.Write(Answer(InputText.Read(file, console.In)));
        return ExitCodes.Success;
    }

    /// <summary>The whole output for the input <paramref name="text"/>, ending in a newline.</summary>
    /// <param name="text">The input document.</param>
    /// <exception cref="InputException">The input is malformed or invalid.</exception>
    protected abstract string Answer(string text);

    /// <summary>The command's <c>--help</c>, ending in a newline.</summary>
    protected abstract string HelpText();
}
