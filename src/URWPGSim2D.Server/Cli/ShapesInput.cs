namespace URWPGSim2D.Server.Cli;

/// <summary>The input of <c>shapes</c> (and the shapes form of <c>render</c>): a JSON array of SHAPE objects, named <c>shapes</c> in error paths.</summary>
internal static class ShapesInput
{
    /// <summary>The user-facing name of the input array, the root of every error path.</summary>
    public const string RootName = "shapes";

    /// <summary>Parses and validates the whole input; the first problem in document order is reported.</summary>
    /// <param name="text">The input text.</param>
    /// <returns>The shapes, in input order.</returns>
    /// <exception cref="InputException">Malformed JSON or an invalid SHAPE (<c>shapes[3].joints: ...</c>).</exception>
    /// <param name="limit">The most SHAPEs accepted (<see cref="InputLimits"/>).</param>
    /// <param name="command">The command reading them, for the limit's message.</param>
    public static InputShape[] Read(string text, int limit = InputLimits.Shapes, string command = "shapes")
    {
        InputLimits.CheckCount(text, RootName, limit, command);
        var dtos = JsonInput.Deserialize(text, InputJsonContext.Default.ShapeDtoArray, RootName, ExpectedKind)
            ?? throw new InputException(RootName, "must be an array of SHAPE objects, got null");
        var shapes = new InputShape[dtos.Length];
        for (int i = 0; i < dtos.Length; i++)
        {
            string path = $"{RootName}[{i}]";
            shapes[i] = ShapeJson.Read(dtos[i] ?? throw new InputException(path, "must be a shape object {\"type\": ..., ...}, got null"), path);
        }

        return shapes;
    }

    // The schema of the input document, for "expected ..." messages.
    private static string? ExpectedKind(ReadOnlySpan<JsonPathSegment> path) => path switch
    {
        [] => "an array of SHAPE objects",
        [{ IsIndex: true }, ..] => ShapeSchema.ExpectedKind(path[1..]),
        _ => null,
    };
}
