using System.Text.Json;
using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>collide FILE</c>: reads a JSON array of <c>{"a": SHAPE, "b": SHAPE}</c> pairs and writes,
/// in the same order, one compact JSON array of <c>{"intersect", "mtv", "normal", "actionPoint"}</c>
/// results from <see cref="CollisionDetector"/>, or, for a pair with a fish, from
/// <see cref="FishCollision"/> followed by <c>"partA"</c> and <c>"partB"</c>. Every pair is
/// validated before anything is written: on bad input stdout stays empty.
/// </summary>
internal sealed class CollideCommand : JsonFileCommand
{
    /// <summary>The user-facing name of the input array, the root of every error path.</summary>
    public const string RootName = "pairs";

    /// <summary>Declares the command.</summary>
    public CollideCommand()
        : base("collide", "Test pairs of shapes from a JSON file for collision; results as JSON on stdout.", "pairs of shapes (JSON), - for stdin")
    {
    }

    /// <inheritdoc />
    protected override string Answer(string text)
    {
        var pairs = ReadPairs(text);
        var contacts = new FishContact[pairs.Length];
        var withParts = new bool[pairs.Length];
        for (int i = 0; i < pairs.Length; i++)
        {
            contacts[i] = InputCollision.Detect(pairs[i].A, pairs[i].B);
            withParts[i] = InputCollision.HasParts(pairs[i].A, pairs[i].B);
        }

        return CollideOutput.Format(contacts, withParts) + "\n";
    }

    /// <summary>Parses and validates the whole input; the first problem in document order is reported.</summary>
    /// <param name="text">The input text.</param>
    /// <returns>The shape pairs, in input order.</returns>
    /// <exception cref="InputException">Malformed JSON or an invalid pair.</exception>
    /// <param name="limit">The most pairs accepted (<see cref="InputLimits"/>).</param>
    /// <param name="command">The command reading them, for the limit's message.</param>
    internal static (InputShape A, InputShape B)[] ReadPairs(string text, int limit = InputLimits.Pairs, string command = "collide")
    {
        InputLimits.CheckCount(text, RootName, limit, command);
        var dtos = JsonInput.Deserialize(text, InputJsonContext.Default.PairDtoArray, RootName, ExpectedKind)
            ?? throw new InputException(RootName, "must be an array of {\"a\": SHAPE, \"b\": SHAPE} objects, got null");
        var pairs = new (InputShape A, InputShape B)[dtos.Length];
        for (int i = 0; i < dtos.Length; i++)
        {
            string path = $"{RootName}[{i}]";
            var dto = dtos[i] ?? throw new InputException(path, "must be an object {\"a\": SHAPE, \"b\": SHAPE}, got null");
            pairs[i] = (ShapeJson.Read(dto.A, path + ".a"), ShapeJson.Read(dto.B, path + ".b"));
        }

        return pairs;
    }

    // The schema of the input document, for "expected ..." messages.
    private static string? ExpectedKind(ReadOnlySpan<JsonPathSegment> path) => path switch
    {
        [] => "an array of {\"a\": SHAPE, \"b\": SHAPE} objects",
        [{ IsIndex: true }] => "an object {\"a\": SHAPE, \"b\": SHAPE}",
        [{ IsIndex: true }, { Name: "a" or "b" }, ..] => ShapeSchema.ExpectedKind(path[2..]),
        _ => null,
    };

    /// <inheritdoc />
    protected override string HelpText() =>
        ($$"""
        Usage: {{Usage}}

        Reads FILE (- for stdin): a JSON array of {"a": SHAPE, "b": SHAPE} pairs, coordinates [x, z] in mm.
        SHAPE is one of:

        """ + ShapeGrammar.HelpLines + """
        Writes to stdout one line: a JSON array, in input order, of
          {"intersect":bool,"mtv":[x,z],"normal":[x,z],"actionPoint":[x,z]}
        and, when a or b is a fish, also "partA" and "partB": the fish leaf in the deepest contact
        (leftPectoral, body, rightPectoral, tail1, tail2, tail3, leftCaudal, rightCaudal), null for a
        side that is not a fish or when they do not intersect. Pairs without a fish have no part fields.
        mtv moves a out of b; normal is the unit vector from b toward a; actionPoint lies in the overlap.
        All three are [0,0] when the shapes do not overlap (touching is not overlapping).
        Bad input: one line "PATH: problem" on stderr (e.g. pairs[3].a.radius: must be > 0, got -5), exit code 2.

        """).ReplaceLineEndings("\n");
}
