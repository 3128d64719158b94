using System.Text.Json;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Messages;
using URWPGSim2D.Strategies;
using static URWPGSim2D.Engine.Scenario.JsonReader;

namespace URWPGSim2D.Engine.Items.Catalog;

/// <summary>
/// A scenario file with <c>"item": NAME</c>: the item's layout and rules, with the file's
/// <c>cycles</c>, <c>seed</c> and <c>noise</c>, and optionally <c>fish</c> and <c>balls</c> whose
/// entries override the item's first fish or balls, in the item's order (
/// fish <c>position</c>, <c>heading</c>, <c>strategy</c> (idle, chase-ball, fixed, demo) and
/// <c>decision</c>; ball <c>position</c> and <c>velocity</c>). Sizes, obstacles, zones and values
/// stay the item's.
/// </summary>
internal static class ItemScenarioParser
{
    /// <summary>Parses the root object of an item scenario.</summary>
    public static ScenarioDefinition Parse(JsonElement root, JsonElement itemName)
    {
        OnlyKnown(root, string.Empty, "item", "cycles", "seed", "noise", "fish", "balls");
        string name = Text(itemName, "item");
        CompetitionItem item = ItemRegistry.Find(name)
            ?? throw new ScenarioException("item", $"must be one of {string.Join(", ", Slugs())} (or the original's name), got {MessageText.Quote(name)}");
        ulong seed = root.TryGetProperty("seed", out var se) ? (ulong)Integer(se, "seed", 0, long.MaxValue) : 1;
        var s = item.CreateScenario(seed) with { Seed = seed };
        if (root.TryGetProperty("cycles", out var cycles))
        {
            s = s with { Cycles = (int)Integer(cycles, "cycles", 0, int.MaxValue) };
        }

        if (root.TryGetProperty("noise", out var noise))
        {
            s = s with { Noise = Boolean(noise, "noise") };
        }

        if (root.TryGetProperty("fish", out var fish))
        {
            s = s with { Fish = Override(fish, "fish", s.Fish, (e, p, d) => ReadFish(e, p, d, s)), FishOverridden = true };
        }

        if (root.TryGetProperty("balls", out var balls))
        {
            s = s with { Balls = Override(balls, "balls", s.Balls, (e, p, d) => ReadBall(e, p, d, s)) };
        }

        return s;
    }

    private static IEnumerable<string> Slugs()
    {
        foreach (var item in ItemRegistry.All)
        {
            yield return item.Slug;
        }
    }

    private static List<T> Override<T>(JsonElement array, string name, IReadOnlyList<T> defaults, Func<JsonElement, string, T, T> read)
    {
        ArrayOf(array, name);
        if (array.GetArrayLength() > defaults.Count)
        {
            throw new ScenarioException(name, $"the item has {defaults.Count}, got {array.GetArrayLength()} (entries override the item's first ones, in its order)");
        }

        var list = new List<T>(defaults);
        int i = 0;
        foreach (var e in array.EnumerateArray())
        {
            list[i] = read(e, $"{name}[{i}]", defaults[i]);
            i++;
        }

        return list;
    }

    private static FishDefinition ReadFish(JsonElement e, string path, FishDefinition d, ScenarioDefinition s)
    {
        Object(e, path);
        OnlyKnown(e, path, "position", "heading", "strategy", "decision");
        bool placed = e.TryGetProperty("position", out var p);
        Vector2 position = placed ? Vector(p, path + ".position") : d.Position; // the item's own pose may be a parking place off the field
        if (placed && (MathF.Abs(position.X) >= s.FieldLength * 0.5f || MathF.Abs(position.Y) >= s.FieldWidth * 0.5f))
        {
            throw new ScenarioException(path + ".position", $"must be inside the field (|x| < {s.FieldLength * 0.5f}, |z| < {s.FieldWidth * 0.5f}), got [{position.X}, {position.Y}]");
        }

        float heading = e.TryGetProperty("heading", out var h) ? Number(h, path + ".heading") : d.Heading;
        bool hasDecision = e.TryGetProperty("decision", out var de);
        string strategy = e.TryGetProperty("strategy", out var st) ? Text(st, path + ".strategy") : hasDecision ? "fixed" : d.Strategy;
        if (strategy is not ("idle" or "chase-ball" or "fixed" or "demo"))
        {
            throw new ScenarioException(path + ".strategy", $"must be \"idle\", \"chase-ball\", \"fixed\" or \"demo\", got {MessageText.Quote(strategy)}");
        }

        Decision decision = Decision.Stop;
        if (strategy == "fixed")
        {
            if (!hasDecision)
            {
                throw new ScenarioException(path + ".decision", "is required for strategy \"fixed\"");
            }

            Object(de, path + ".decision");
            OnlyKnown(de, path + ".decision", "vcode", "tcode");
            int v = de.TryGetProperty("vcode", out var ve) ? (int)Integer(ve, path + ".decision.vcode", 0, 15) : throw new ScenarioException(path + ".decision.vcode", "is required");
            int t = de.TryGetProperty("tcode", out var te) ? (int)Integer(te, path + ".decision.tcode", 0, 15) : throw new ScenarioException(path + ".decision.tcode", "is required");
            decision = new Decision(v, t);
        }
        else if (hasDecision)
        {
            throw new ScenarioException(path + ".decision", $"is only for strategy \"fixed\", not {MessageText.Quote(strategy)}");
        }

        return d with { Position = position, Heading = heading, Strategy = strategy, Decision = decision };
    }

    private static BallDefinition ReadBall(JsonElement e, string path, BallDefinition d, ScenarioDefinition s)
    {
        Object(e, path);
        OnlyKnown(e, path, "position", "velocity");
        Vector2 position = e.TryGetProperty("position", out var p) ? Vector(p, path + ".position") : d.Position;
        Vector2 velocity = e.TryGetProperty("velocity", out var v) ? Vector(v, path + ".velocity") : d.Velocity;
        if (MathF.Abs(position.X) + d.Radius > s.FieldLength * 0.5f || MathF.Abs(position.Y) + d.Radius > s.FieldWidth * 0.5f)
        {
            throw new ScenarioException(path + ".position", $"the ball (radius {d.Radius}) must lie inside the field, got [{position.X}, {position.Y}]");
        }

        return d with { Position = position, Velocity = velocity };
    }
}
