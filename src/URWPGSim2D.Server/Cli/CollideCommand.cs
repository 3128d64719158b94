using System;
using System.Text.Json;
using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Server.Json;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>collide FILE</c>: reads a JSON array of <c>{"a": SHAPE, "b": SHAPE}</c> pairs and writes,
/// in the same order, one compact JSON array of <c>{"intersect", "mtv", "normal", "actionPoint"}</c>
/// results from <see cref="CollisionDetector.Detect(in Shape, in Shape)"/>. Every pair is
/// validated before anything is written: on bad input stdout stays empty.
/// </summary>
internal sealed class CollideCommand : ICliCommand
{
    /// <summary>The user-facing name of the input array, the root of every error path.</summary>
    public const string RootName = "pairs";

    /// <inheritdoc />
    public string Name => "collide";

    /// <inheritdoc />
    public string Synopsis => "collide FILE";

    /// <inheritdoc />
    public string Summary => "Test pairs of shapes from a JSON file for collision; results as JSON on stdout.";

    private string Usage => $"{CliApp.ProgramName} {Synopsis}";

    /// <inheritdoc />
    public int Run(ReadOnlySpan<string> arguments, CliConsole console)
    {
        if (arguments.Length == 1 && CliApp.IsHelp(arguments[0]))
        {
            console.Out.Write(HelpText());
            return ExitCodes.Success;
        }

        string file = ParseArguments(arguments);
        string text = InputText.Read(file, console.In);
        var pairs = ReadPairs(text);
        var results = new CollisionResultDto[pairs.Length];
        for (int i = 0; i < pairs.Length; i++)
        {
            results[i] = CollisionResultDto.From(CollisionDetector.Detect(in pairs[i].A, in pairs[i].B));
        }

        string json = JsonSerializer.Serialize(results, OutputJsonContext.Default.CollisionResultDtoArray);
        console.Out.Write(json + "\n");
        return ExitCodes.Success;
    }

    /// <summary>Parses and validates the whole input; the first problem in document order is reported.</summary>
    /// <param name="text">The input text.</param>
    /// <returns>The shape pairs, in input order.</returns>
    /// <exception cref="CliInputException">Malformed JSON or an invalid pair.</exception>
    internal static (Shape A, Shape B)[] ReadPairs(string text)
    {
        var dtos = JsonInput.Deserialize(text, InputJsonContext.Default.PairDtoArray, RootName, ExpectedKind)
            ?? throw new CliInputException(RootName, "must be an array of {\"a\": SHAPE, \"b\": SHAPE} objects, got null");
        var pairs = new (Shape A, Shape B)[dtos.Length];
        for (int i = 0; i < dtos.Length; i++)
        {
            string path = $"{RootName}[{i}]";
            var dto = dtos[i] ?? throw new CliInputException(path, "must be an object {\"a\": SHAPE, \"b\": SHAPE}, got null");
            pairs[i] = (ShapeJson.ToShape(dto.A, path + ".a"), ShapeJson.ToShape(dto.B, path + ".b"));
        }

        return pairs;
    }

    private string ParseArguments(ReadOnlySpan<string> arguments)
    {
        if (arguments.Length != 1)
        {
            throw new CliUsageException($"collide: expected one FILE argument (- for stdin), got {arguments.Length}", Usage);
        }

        string file = arguments[0];
        if (file.Length == 0)
        {
            throw new CliUsageException("collide: FILE is empty", Usage);
        }

        if (file.StartsWith('-') && file != InputText.StandardInput)
        {
            throw new CliUsageException($"collide: unknown option {CliText.Quote(file)}", Usage);
        }

        return file;
    }

    // The schema of the input document, for "expected ..." messages.
    private static string? ExpectedKind(ReadOnlySpan<JsonPathSegment> path) => path switch
    {
        [] => "an array of {\"a\": SHAPE, \"b\": SHAPE} objects",
        [{ IsIndex: true }] => "an object {\"a\": SHAPE, \"b\": SHAPE}",
        [{ IsIndex: true }, { Name: "a" or "b" }, ..] => ShapeSchema.ExpectedKind(path[2..]),
        _ => null,
    };

    private string HelpText() =>
        $$"""
        Usage: {{Usage}}

        Reads FILE (- for stdin): a JSON array of {"a": SHAPE, "b": SHAPE} pairs, coordinates [x, z] in mm.
        SHAPE is one of:
          {"type":"circle","center":[x,z],"radius":r}
          {"type":"aabb","min":[x,z],"max":[x,z]}
          {"type":"kdop8","min":[s0,s1,s2,s3],"max":[s0,s1,s2,s3]}   slabs along (1,0), (0,1), (√½,√½), (√½,−√½)
          {"type":"polygon","vertices":[[x,z],...]}                  convex, either winding, 3 to 64 vertices
          {"type":"segment","a":[x,z],"b":[x,z]}
        Writes to stdout one line: a JSON array, in input order, of
          {"intersect":bool,"mtv":[x,z],"normal":[x,z],"actionPoint":[x,z]}
        mtv moves a out of b; normal is the unit vector from b toward a; actionPoint lies in the overlap.
        All three are [0,0] when the shapes do not overlap (touching is not overlapping).
        Bad input: one line "PATH: problem" on stderr (e.g. pairs[3].a.radius: must be > 0, got -5), exit code 2.

        """.ReplaceLineEndings("\n");
}
