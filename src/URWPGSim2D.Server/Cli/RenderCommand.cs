using URWPGSim2D.Server.Rendering;
using URWPGSim2D.Tournament.Batch;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>render FILE --svg OUT</c>: draws the SHAPEs, or the <c>{"a", "b"}</c> pairs and their
/// collision results, of FILE as an SVG picture (<see cref="ShapeFigure"/>). The whole input is
/// validated and the picture built in memory first; OUT is then written through a temporary
/// file and a rename, so on any error nothing is written. <c>--svg -</c> writes the SVG to stdout.
/// </summary>
internal sealed class RenderCommand : ICliCommand
{
    /// <inheritdoc />
    public string Name => "render";

    /// <inheritdoc />
    public string Synopsis => $"{Name} {Line.Text}";

    /// <inheritdoc />
    public string Summary => "Draw shapes or pairs (fish trees, outer circles, MTV, normal, action point) as an SVG file.";

    private static readonly Option<bool> HelpOption = CliSyntax.Help();
    private static readonly Option<string> SvgOption = CliSyntax.Value("--svg", "OUT", "the SVG file to write (- for stdout)", CliCompletions.Paths);

    /// <inheritdoc />
    public Command Syntax { get; } = CliSyntax.Command("render", "Draw shapes or pairs as SVG.", Line, HelpOption);

    private static readonly UsageLine Line = new(FileArgument.Declare("shapes or pairs (JSON), - for stdin"), SvgOption);

    private string Usage => $"{CliApp.ProgramName} {Synopsis}";

    /// <inheritdoc />
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (words.Count == 1 && words[0].Option == HelpOption)
        {
            console.Out.Write(HelpText());
            return ExitCodes.Success;
        }

        var (file, output) = ParseArguments(words);
        string text = InputText.Read(file, console.In);
        string svg = RenderInputKind.IsPairs(text) ? RenderPairs(text) : RenderShapes(text);
        if (output == InputText.StandardInput)
        {
            console.Out.Write(svg);
            return ExitCodes.Success;
        }

        try
        {
            AtomicFile.WriteAllText(output, svg);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new InputException(output, $"cannot write file: {ex.Message.ReplaceLineEndings(" ")}");
        }

        return ExitCodes.Success;
    }

    private static string RenderShapes(string text)
    {
        var shapes = ShapesInput.Read(text, InputLimits.RenderElements, "render");
        var items = new FigureShape[shapes.Length];
        for (int i = 0; i < shapes.Length; i++)
        {
            items[i] = new FigureShape(shapes[i], $"{ShapesInput.RootName}[{i}]", FigureRole.Single);
        }

        return ShapeFigure.Render(items, []);
    }

    private static string RenderPairs(string text)
    {
        var pairs = CollideCommand.ReadPairs(text, InputLimits.RenderElements, "render");
        var items = new List<FigureShape>(2 * pairs.Length);
        var contacts = new FigureContact[pairs.Length];
        for (int i = 0; i < pairs.Length; i++)
        {
            string label = $"{CollideCommand.RootName}[{i}]";
            var (a, b) = pairs[i];
            items.Add(new FigureShape(b, label + ".b", FigureRole.B));
            items.Add(new FigureShape(a, label + ".a", FigureRole.A));
            contacts[i] = new FigureContact(InputCollision.Detect(a, b), label, InputCollision.HasParts(a, b));
        }

        return ShapeFigure.Render(items, contacts);
    }

    private (string File, string Output) ParseArguments(IReadOnlyList<CommandLineWord> words)
    {
        string? file = null, output = null;
        int files = 0;
        foreach (var word in words)
        {
            if (word.Option == SvgOption)
            {
                if (output is not null)
                {
                    throw new CliUsageException("render: --svg given twice", Usage);
                }

                if (word.Value is null || word.Value.Length == 0)
                {
                    throw new CliUsageException("render: --svg needs a file name (- for stdout)", Usage);
                }

                output = word.Value;
                continue;
            }

            file = FileArgument.Check(Name, word.Text, Syntax, Usage);
            files++;
        }

        if (files != 1)
        {
            throw new CliUsageException($"render: expected one FILE argument (- for stdin), got {files}", Usage);
        }

        if (output is null)
        {
            throw new CliUsageException("render: --svg OUT is required", Usage);
        }

        return (file!, output);
    }

    private string HelpText() =>
        ($$"""
        Usage: {{Usage}}

        Reads FILE (- for stdin): a JSON array of SHAPEs, or a JSON array of {"a": SHAPE, "b": SHAPE} pairs as for
        collide (it is read as pairs when its first element has an "a" or "b" field and no "type" field).
        Coordinates [x, z] in mm. SHAPE is one of:

        """ + ShapeGrammar.HelpLines + """
        Writes an SVG picture to OUT (- for stdout), +X right, +Z down, fitted to the content, with a legend:
        a fish's eight leaf polygons, leaf 8-DOPs and root / body group / tail group circles; other shapes and
        their outer circles; for each intersecting pair the MTV (true length, from the action point), the
        normal (from b toward a) and the action point. Labels are the input paths (shapes[2], pairs[0].a).
        OUT is written through a temporary file and a rename; on bad input nothing is written.
        Bad input: one line "PATH: problem" on stderr (e.g. pairs[0].a.size.width: must be > 0, got 0), exit code 2.

        """).ReplaceLineEndings("\n");
}
