using System.Globalization;
using System.Text.Json;
using URWPGSim2D.Engine.Messages;

namespace URWPGSim2D.Engine.Scenario;

/// <summary>Typed reads of scenario values that fail with the value's JSON path.</summary>
internal static class JsonReader
{
    /// <summary>Fails on any property not in <paramref name="allowed"/>.</summary>
    public static void OnlyKnown(JsonElement obj, string path, params string[] allowed)
    {
        foreach (var p in obj.EnumerateObject())
        {
            string name = Name(p, path);
            if (Array.IndexOf(allowed, name) < 0)
            {
                throw new ScenarioException(Join(path, MessageText.Escape(name)), $"unknown property (expected one of: {string.Join(", ", allowed)})");
            }
        }
    }

    /// <summary>The object at <paramref name="path"/>, or a failure.</summary>
    public static JsonElement Object(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.Object)
        {
            throw new ScenarioException(path, $"must be an object, got {Describe(e)}");
        }

        return e;
    }

    /// <summary>A finite number.</summary>
    public static float Number(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.Number || !e.TryGetDouble(out double d) || !double.IsFinite(d) || !float.IsFinite((float)d))
        {
            throw new ScenarioException(path, $"must be a number, got {Describe(e)}");
        }

        return (float)d;
    }

    /// <summary>A number &gt; 0.</summary>
    public static float Positive(JsonElement e, string path)
    {
        float v = Number(e, path);
        if (!(v > 0f))
        {
            throw new ScenarioException(path, $"must be > 0, got {Raw(e)}");
        }

        return v;
    }

    /// <summary>An integer in [min, max].</summary>
    public static long Integer(JsonElement e, string path, long min, long max)
    {
        if (e.ValueKind != JsonValueKind.Number || !e.TryGetInt64(out long v))
        {
            throw new ScenarioException(path, $"must be an integer, got {Describe(e)}");
        }

        if (v < min || v > max)
        {
            throw new ScenarioException(path, $"must be {min.ToString(CultureInfo.InvariantCulture)}..{max.ToString(CultureInfo.InvariantCulture)}, got {Raw(e)}");
        }

        return v;
    }

    /// <summary>true or false.</summary>
    public static bool Boolean(JsonElement e, string path) => e.ValueKind switch
    {
        JsonValueKind.True => true,
        JsonValueKind.False => false,
        _ => throw new ScenarioException(path, $"must be true or false, got {Describe(e)}"),
    };

    /// <summary>A string.</summary>
    public static string Text(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.String)
        {
            throw new ScenarioException(path, $"must be a string, got {Describe(e)}");
        }

        try
        {
            return e.GetString()!;
        }
        catch (InvalidOperationException)
        {
            throw new ScenarioException(path, $"must be valid UTF-16 text, got {Raw(e)} (a lone surrogate)");
        }
    }

    /// <summary>A property's name; a name that is not valid UTF-16 (a lone surrogate escape) fails with its raw text.</summary>
    public static string Name(JsonProperty p, string path)
    {
        try
        {
            return p.Name;
        }
        catch (InvalidOperationException)
        {
            string raw = p.ToString();
            throw new ScenarioException(path, $"property names must be valid UTF-16 text, got {(raw.Length <= 40 ? raw : raw[..37] + "...")} (a lone surrogate)");
        }
    }

    /// <summary>An [x, z] pair of finite numbers.</summary>
    public static Vector2 Vector(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.Array || e.GetArrayLength() != 2)
        {
            throw new ScenarioException(path, $"must be [x, z], got {Describe(e)}");
        }

        return new Vector2(Number(e[0], path + "[0]"), Number(e[1], path + "[1]"));
    }

    /// <summary>An array.</summary>
    public static JsonElement ArrayOf(JsonElement e, string path) =>
        e.ValueKind == JsonValueKind.Array ? e : throw new ScenarioException(path, $"must be an array, got {Describe(e)}");

    /// <summary>"a.b" or "b" at the root.</summary>
    public static string Join(string path, string name) => path.Length == 0 ? name : $"{path}.{name}";

    /// <summary>The value's JSON text, shortened.</summary>
    public static string Raw(JsonElement e)
    {
        string text = e.GetRawText().ReplaceLineEndings(" ");
        return text.Length <= 40 ? text : text[..37] + "...";
    }

    private static string Describe(JsonElement e) => e.ValueKind switch
    {
        JsonValueKind.Object => "an object",
        JsonValueKind.Array => "an array",
        JsonValueKind.String => $"the string {Raw(e)}",
        JsonValueKind.Null => "null",
        _ => Raw(e),
    };
}
