using System.Text.Json;
using URWPGSim2D.Engine.Messages;
using static URWPGSim2D.Engine.Scenario.JsonReader;

namespace URWPGSim2D.Engine.Scenario;

/// <summary>
/// Reads a scenario file (System.Text.Json; comments and trailing commas allowed). Everything but
/// "fish" and "balls" has a default. Any problem throws <see cref="ScenarioException"/> naming the
/// JSON path. Fish must have their centre inside the field, balls and obstacles must lie inside it.
/// </summary>
internal static class ScenarioParser
{
    /// <summary>Most bodies (fish + balls + obstacles) of a scenario file.</summary>
    public const int MaxBodies = 20_000;

    private static readonly JsonDocumentOptions Options = new() { AllowTrailingCommas = true, CommentHandling = JsonCommentHandling.Skip, MaxDepth = 16 };

    /// <summary>Parses and validates the JSON text of a scenario that names no item (a scenario file with <c>"item"</c> is read by <c>Items.Catalog.ScenarioFile</c>).</summary>
    public static ScenarioDefinition Parse(string json) => ParseDocument(json, ReadPlain);

    /// <summary>Parses <paramref name="json"/> as scenario JSON (comments and trailing commas allowed) and reads its root object with <paramref name="read"/>; a syntax error or lone surrogate is a <see cref="ScenarioException"/>.</summary>
    /// <param name="json">The text.</param>
    /// <param name="read">Reads the root object (already checked to be an object).</param>
    public static ScenarioDefinition ParseDocument(string json, Func<JsonElement, ScenarioDefinition> read)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(json, Options);
        }
        catch (JsonException e)
        {
            string where = e.LineNumber is long line ? $"line {line + 1}, column {(e.BytePositionInLine ?? 0) + 1}" : "somewhere";
            throw new ScenarioException(string.Empty, $"invalid JSON at {where}");
        }

        using (doc)
        {
            try
            {
                return read(Object(doc.RootElement, "(root)"));
            }
            catch (InvalidOperationException)
            {
                throw new ScenarioException(string.Empty, LoneSurrogate.Describe(json, new JsonReaderOptions { AllowTrailingCommas = true, CommentHandling = JsonCommentHandling.Skip }));
            }
        }
    }

    /// <summary>Reads the root object of a scenario that names no item.</summary>
    /// <param name="root">The root object.</param>
    public static ScenarioDefinition ReadPlain(JsonElement root)
    {
        OnlyKnown(root, string.Empty, "field", "cycles", "seed", "noise", "fish", "balls", "obstacles");
        var s = new ScenarioDefinition();
        if (root.TryGetProperty("field", out var field))
        {
            s = ReadField(field, s);
        }

        if (root.TryGetProperty("cycles", out var cycles))
        {
            s = s with { Cycles = (int)Integer(cycles, "cycles", 0, int.MaxValue) };
        }

        if (root.TryGetProperty("seed", out var seed))
        {
            s = s with { Seed = (ulong)Integer(seed, "seed", 0, long.MaxValue) };
        }

        if (root.TryGetProperty("noise", out var noise))
        {
            s = s with { Noise = Boolean(noise, "noise") };
        }

        long bodies = Count(root, "fish") + Count(root, "balls") + Count(root, "obstacles");
        if (bodies > MaxBodies)
        {
            throw new ScenarioException(string.Empty, $"{bodies} bodies (fish, balls and obstacles), more than the limit of {MaxBodies} (docs/cli.md, Limits)");
        }

        s = s with
        {
            Fish = ReadList(root, "fish", required: true, (e, p) => ReadFish(e, p, s)),
            Balls = ReadList(root, "balls", required: true, (e, p) => ReadBall(e, p, s)),
            Obstacles = ReadList(root, "obstacles", required: false, (e, p) => ReadObstacle(e, p, s)),
        };
        return s;
    }

    private static ScenarioDefinition ReadField(JsonElement e, ScenarioDefinition s)
    {
        Object(e, "field");
        OnlyKnown(e, "field", "length", "width", "goalBlocks");
        float length = e.TryGetProperty("length", out var l) ? Positive(l, "field.length") : s.FieldLength;
        float width = e.TryGetProperty("width", out var w) ? Positive(w, "field.width") : s.FieldWidth;
        bool blocks = !e.TryGetProperty("goalBlocks", out var g) || Boolean(g, "field.goalBlocks");
        if (length < 600f)
        {
            throw new ScenarioException("field.length", $"must be >= 600 (room for a fish and both goals), got {length}");
        }

        if (width < 600f)
        {
            throw new ScenarioException("field.width", $"must be >= 600 (room for a fish and the goal mouth), got {width}");
        }

        return s with { FieldLength = length, FieldWidth = width, GoalBlocks = blocks };
    }

    private static List<T> ReadList<T>(JsonElement root, string name, bool required, Func<JsonElement, string, T> read)
    {
        var list = new List<T>();
        if (!root.TryGetProperty(name, out var array))
        {
            return required ? throw new ScenarioException(name, "is required") : list;
        }

        ArrayOf(array, name);
        int i = 0;
        foreach (var item in array.EnumerateArray())
        {
            list.Add(read(item, $"{name}[{i++}]"));
        }

        return list;
    }

    private static FishDefinition ReadFish(JsonElement e, string path, ScenarioDefinition s)
    {
        Object(e, path);
        OnlyKnown(e, path, "team", "position", "heading", "strategy", "decision", "tailPhase");
        int team = e.TryGetProperty("team", out var t) ? (int)Integer(t, path + ".team", 0, 1) : throw new ScenarioException(path + ".team", "is required");
        Vector2 position = Required(e, path, "position");
        if (MathF.Abs(position.X) >= s.FieldLength * 0.5f || MathF.Abs(position.Y) >= s.FieldWidth * 0.5f)
        {
            throw new ScenarioException(path + ".position", $"must be inside the field (|x| < {s.FieldLength * 0.5f}, |z| < {s.FieldWidth * 0.5f}), got [{position.X}, {position.Y}]");
        }

        float heading = e.TryGetProperty("heading", out var h) ? Number(h, path + ".heading") : 0f;
        float tailPhase = e.TryGetProperty("tailPhase", out var tp) ? Number(tp, path + ".tailPhase") : 0f;
        bool hasDecision = e.TryGetProperty("decision", out var d);
        string strategy = e.TryGetProperty("strategy", out var st) ? Text(st, path + ".strategy") : hasDecision ? "fixed" : "idle";
        if (strategy is not ("idle" or "chase-ball" or "fixed"))
        {
            throw new ScenarioException(path + ".strategy", $"must be \"idle\", \"chase-ball\" or \"fixed\", got {MessageText.Quote(strategy)}");
        }

        Decision decision = Decision.Stop;
        if (strategy == "fixed")
        {
            if (!hasDecision)
            {
                throw new ScenarioException(path + ".decision", "is required for strategy \"fixed\"");
            }

            decision = ReadDecision(d, path + ".decision");
        }
        else if (hasDecision)
        {
            throw new ScenarioException(path + ".decision", $"is only for strategy \"fixed\", not {MessageText.Quote(strategy)}");
        }

        return new FishDefinition(team, position, heading, strategy, decision, tailPhase);
    }

    private static Decision ReadDecision(JsonElement e, string path)
    {
        Object(e, path);
        OnlyKnown(e, path, "vcode", "tcode");
        int v = e.TryGetProperty("vcode", out var ve) ? (int)Integer(ve, path + ".vcode", 0, 15) : throw new ScenarioException(path + ".vcode", "is required");
        int t = e.TryGetProperty("tcode", out var te) ? (int)Integer(te, path + ".tcode", 0, 15) : throw new ScenarioException(path + ".tcode", "is required");
        return new Decision(v, t);
    }

    private static BallDefinition ReadBall(JsonElement e, string path, ScenarioDefinition s)
    {
        Object(e, path);
        OnlyKnown(e, path, "position", "velocity", "radius");
        Vector2 position = Required(e, path, "position");
        Vector2 velocity = e.TryGetProperty("velocity", out var v) ? Vector(v, path + ".velocity") : Vector2.Zero;
        float radius = e.TryGetProperty("radius", out var r) ? Positive(r, path + ".radius") : 58f;
        if (MathF.Abs(position.X) + radius > s.FieldLength * 0.5f || MathF.Abs(position.Y) + radius > s.FieldWidth * 0.5f)
        {
            throw new ScenarioException(path + ".position", $"the ball (radius {radius}) must lie inside the field, got [{position.X}, {position.Y}]");
        }

        return new BallDefinition(position, velocity, radius);
    }

    private static ObstacleDefinition ReadObstacle(JsonElement e, string path, ScenarioDefinition s)
    {
        Object(e, path);
        string type = e.TryGetProperty("type", out var t) ? Text(t, path + ".type") : throw new ScenarioException(path + ".type", "is required");
        Vector2 center;
        if (type == "rectangle")
        {
            OnlyKnown(e, path, "type", "center", "length", "width", "heading");
            center = Required(e, path, "center");
            float length = e.TryGetProperty("length", out var l) ? Positive(l, path + ".length") : 100f;
            float width = e.TryGetProperty("width", out var w) ? Positive(w, path + ".width") : 100f;
            float largest = MathF.Max(s.FieldLength, s.FieldWidth);
            if (length > largest || width > largest)
            {
                string which = length > largest ? "length" : "width";
                throw new ScenarioException($"{path}.{which}", $"must be at most the field's larger side ({largest}), got {(length > largest ? length : width)}");
            }

            float heading = e.TryGetProperty("heading", out var h) ? Number(h, path + ".heading") : 0f;
            Inside(s, path, center, 0f);
            return new ObstacleDefinition(ObstacleKind.Rectangle, center, length, width, heading, 0f);
        }

        if (type == "round")
        {
            OnlyKnown(e, path, "type", "center", "radius");
            center = Required(e, path, "center");
            float radius = e.TryGetProperty("radius", out var r) ? Positive(r, path + ".radius") : 58f;
            Inside(s, path, center, radius);
            return new ObstacleDefinition(ObstacleKind.Round, center, 2f * radius, 2f * radius, 0f, radius);
        }

        throw new ScenarioException(path + ".type", $"must be \"rectangle\" or \"round\", got {MessageText.Quote(type)}");
    }

    private static void Inside(ScenarioDefinition s, string path, Vector2 center, float radius)
    {
        if (MathF.Abs(center.X) + radius > s.FieldLength * 0.5f || MathF.Abs(center.Y) + radius > s.FieldWidth * 0.5f)
        {
            throw new ScenarioException(path + ".center", $"must lie inside the field, got [{center.X}, {center.Y}]");
        }
    }

    private static long Count(JsonElement root, string name) =>
        root.TryGetProperty(name, out var list) && list.ValueKind == JsonValueKind.Array ? list.GetArrayLength() : 0;

    private static Vector2 Required(JsonElement e, string path, string name) =>
        e.TryGetProperty(name, out var v) ? Vector(v, $"{path}.{name}") : throw new ScenarioException($"{path}.{name}", "is required");
}
