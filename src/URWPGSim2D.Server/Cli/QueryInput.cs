using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Cli;

/// <summary>What a query asks.</summary>
internal enum QueryKind
{
    /// <summary>Distance between shapes a and b.</summary>
    Distance,

    /// <summary>The first shape a ray enters.</summary>
    Ray,

    /// <summary>When a moving shape first touches another.</summary>
    Cast,

    /// <summary>The shapes overlapping a box.</summary>
    Overlap,
}

/// <summary>One validated query of <c>query</c>: shape indices are in range, points finite, the box valid.</summary>
internal readonly record struct InputQuery(QueryKind Kind, int A, int B, Vector2 From, Vector2 To, Aabb Box);

/// <summary>
/// The input of <c>query</c>: <c>{"shapes": [SHAPE…], "queries": [QUERY…]}</c>, parsed and
/// validated whole before anything is computed. Error paths start at the two fields:
/// <c>shapes[2].radius</c>, <c>queries[0].b</c>.
/// </summary>
internal static class QueryInput
{
    /// <summary>Parses and validates the whole input; the first problem in document order is reported.</summary>
    /// <param name="text">The input text.</param>
    /// <returns>The shapes and the queries.</returns>
    /// <exception cref="InputException">Malformed JSON, an invalid SHAPE or an invalid query.</exception>
    public static (InputShape[] Shapes, InputQuery[] Queries) Read(string text)
    {
        QueryInputDto? dto;
        try
        {
            dto = JsonInput.Deserialize(text, InputJsonContext.Default.QueryInputDto, "$", ExpectedKind);
        }
        catch (InputException e) when (e.Path.StartsWith('$'))
        {
            // Paths start at the document's fields: "$.shapes[2]" is shapes[2]; "$" is the document.
            string path = e.Path.Length > 2 ? e.Path[2..] : "input";
            throw new InputException(path, e.Message);
        }

        if (dto is null)
        {
            throw new InputException("input", "must be an object {\"shapes\": [SHAPE, ...], \"queries\": [QUERY, ...]}, got null");
        }

        var shapeDtos = dto.Shapes ?? throw new InputException("shapes", FieldReader.MissingMessage);
        CheckCount(shapeDtos.Length, "shapes", InputLimits.Shapes);
        var shapes = new InputShape[shapeDtos.Length];
        for (int i = 0; i < shapes.Length; i++)
        {
            shapes[i] = ShapeJson.Read(shapeDtos[i], $"shapes[{i}]");
        }

        var queryDtos = dto.Queries ?? throw new InputException("queries", FieldReader.MissingMessage);
        CheckCount(queryDtos.Length, "queries", InputLimits.Pairs);
        var queries = new InputQuery[queryDtos.Length];
        for (int i = 0; i < queries.Length; i++)
        {
            queries[i] = ReadQuery(queryDtos[i], $"queries[{i}]", shapes);
        }

        return (shapes, queries);
    }

    private static InputQuery ReadQuery(QueryDto? dto, string path, InputShape[] shapes)
    {
        if (dto is null)
        {
            throw new InputException(path, FieldReader.MissingMessage);
        }

        var fields = new FieldReader(path);
        string type = fields.String(dto.Type, "type");
        switch (type)
        {
            case "distance":
                return new InputQuery(QueryKind.Distance, Index(dto.A, "a", fields, shapes), Index(dto.B, "b", fields, shapes), default, default, default);
            case "ray":
                return new InputQuery(QueryKind.Ray, -1, -1, Finite(fields.Point(dto.From, "from"), "from", fields), Finite(fields.Point(dto.To, "to"), "to", fields), default);
            case "cast":
                int moving = Index(dto.Shape, "shape", fields, shapes);
                Vector2 translation = Finite(fields.Point(dto.Translation, "translation"), "translation", fields);
                return new InputQuery(QueryKind.Cast, moving, Index(dto.Against, "against", fields, shapes), default, translation, default);
            case "overlap":
                return new InputQuery(QueryKind.Overlap, -1, -1, default, default, Box(dto.Aabb, fields));
            default:
                throw new InputException(fields.PathOf("type"), $"unknown query type {MessageText.Quote(type)} (distance, ray, cast or overlap)");
        }
    }

    private static int Index(int? value, string field, FieldReader fields, InputShape[] shapes)
    {
        int index = value ?? throw fields.Missing(field);
        if ((uint)index >= (uint)shapes.Length)
        {
            throw new InputException(fields.PathOf(field), shapes.Length == 0
                ? $"must be a shape index, but there are no shapes; got {index}"
                : $"must be a shape index 0 … {shapes.Length - 1}, got {index}");
        }

        return index;
    }

    private static Vector2 Finite(Vector2 point, string field, FieldReader fields) =>
        float.IsFinite(point.X) && float.IsFinite(point.Y)
            ? point
            : throw new InputException(fields.PathOf(field), $"must have finite coordinates, got [{point.X}, {point.Y}]");

    private static Aabb Box(QueryBoxDto? dto, FieldReader fields)
    {
        var box = new FieldReader(fields.PathOf("aabb"));
        if (dto is null)
        {
            throw fields.Missing("aabb");
        }

        Vector2 min = box.Point(dto.Min, "min"), max = box.Point(dto.Max, "max");
        try
        {
            return new Aabb(min, max);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, box.ObjectPath, new System.Collections.Generic.Dictionary<string, string> { ["min"] = "min", ["max"] = "max" });
        }
    }

    private static void CheckCount(int count, string path, int limit)
    {
        if (count > limit)
        {
            throw new InputException(path, $"more than {limit} elements, the limit of query (docs/cli.md, Limits)");
        }
    }

    // The schema of the input document, for "expected ..." messages.
    private static string? ExpectedKind(ReadOnlySpan<JsonPathSegment> path) => path switch
    {
        [] => "an object {\"shapes\": [SHAPE, ...], \"queries\": [QUERY, ...]}",
        [{ Name: "shapes" }] => "an array of SHAPE objects",
        [{ Name: "shapes" }, { IsIndex: true }, ..] => ShapeSchema.ExpectedKind(path[2..]),
        [{ Name: "queries" }] => "an array of query objects",
        [{ Name: "queries" }, { IsIndex: true }] => "a query object {\"type\": ..., ...}",
        [{ Name: "queries" }, { IsIndex: true }, { Name: "type" }] => "a string",
        [{ Name: "queries" }, { IsIndex: true }, { Name: "a" or "b" or "shape" or "against" }] => "a shape index (an integer)",
        [{ Name: "queries" }, { IsIndex: true }, { Name: "from" or "to" or "translation" }] => "an array of 2 numbers [x, z]",
        [{ Name: "queries" }, { IsIndex: true }, { Name: "from" or "to" or "translation" }, { IsIndex: true }] => "a number",
        [{ Name: "queries" }, { IsIndex: true }, { Name: "aabb" }] => "an object {\"min\": [x, z], \"max\": [x, z]}",
        [{ Name: "queries" }, { IsIndex: true }, { Name: "aabb" }, { Name: "min" or "max" }] => "an array of 2 numbers [x, z]",
        [{ Name: "queries" }, { IsIndex: true }, { Name: "aabb" }, { Name: "min" or "max" }, { IsIndex: true }] => "a number",
        _ => null,
    };
}
