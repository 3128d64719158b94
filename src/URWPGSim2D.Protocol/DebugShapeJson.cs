using System;
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Protocol;

/// <summary>
/// A strategy's debug drawing as JSON, the same in a <c>decisions</c> message's <c>draw</c> array and in
/// a trace line's <c>draw</c> array (docs/protocol.md, docs/viewer.md):
/// <c>{"kind":"line","fish":1,"from":[x,y],"to":[x,y],"color":"#rrggbb"}</c>; a point and a text have
/// <c>at</c> (a text also <c>text</c>), a circle <c>center</c> and <c>radius</c>. <c>fish</c> and
/// <c>color</c> are left out for the team's drawings in the team's colour.
/// </summary>
internal static class DebugShapeJson
{
    /// <summary>Writes <paramref name="s"/> as one object (with <c>team</c> first when given).</summary>
    public static void Write(Utf8JsonWriter w, in DebugShape s, int team = -1)
    {
        w.WriteStartObject();
        if (team >= 0)
        {
            w.WriteNumber("team", team);
        }

        switch (s.Kind)
        {
            case DebugShapeKind.Point:
                w.WriteString("kind", "point");
                Pair(w, "at", s.A);
                break;
            case DebugShapeKind.Line:
                w.WriteString("kind", "line");
                Pair(w, "from", s.A);
                Pair(w, "to", s.B);
                break;
            case DebugShapeKind.Circle:
                w.WriteString("kind", "circle");
                Pair(w, "center", s.A);
                w.WriteNumber("radius", s.Radius);
                break;
            default:
                w.WriteString("kind", "text");
                Pair(w, "at", s.A);
                w.WriteString("text", s.Text);
                break;
        }

        if (s.Fish >= 0)
        {
            w.WriteNumber("fish", s.Fish);
        }

        if (s.Rgb >= 0)
        {
            Span<char> hex = stackalloc char[7];
            hex[0] = '#';
            s.Rgb.TryFormat(hex[1..], out _, "x6", CultureInfo.InvariantCulture);
            w.WriteString("color", hex);
        }

        w.WriteEndObject();
    }

    /// <summary>Writes every shape of <paramref name="drawings"/> as the array <c>draw</c>.</summary>
    public static void WriteArray(Utf8JsonWriter w, DebugRecorder drawings)
    {
        w.WriteStartArray("draw");
        foreach (ref readonly var s in drawings.Shapes)
        {
            Write(w, s);
        }

        w.WriteEndArray();
    }

    /// <summary>
    /// Reads a <c>draw</c> array (the reader on its property name) into <paramref name="into"/>, which
    /// keeps what fits its bounds; a shape that is not one of the forms above throws <see cref="ProtocolException"/>.
    /// </summary>
    public static void ReadArray(ref Utf8JsonReader r, DebugRecorder into)
    {
        JsonFields.StartArray(ref r, "draw");
        int n = 0;
        while (JsonFields.NextElement(ref r, "draw"))
        {
            if (r.TokenType != JsonTokenType.StartObject)
            {
                throw new ProtocolException($"draw[{n}]: expected an object, got {JsonFields.Describe(ref r)}");
            }

            into.AddShape(ReadShape(ref r, n));
            n++;
        }
    }

    private static DebugShape ReadShape(ref Utf8JsonReader r, int n)
    {
        string? kind = null, text = null;
        int fish = -1, rgb = -1;
        Vector2? a = null, b = null;
        float radius = 0f;
        while (JsonFields.NextProperty(ref r))
        {
            if (r.ValueTextEquals("kind"u8))
            {
                kind = JsonFields.Text(ref r, $"draw[{n}].kind");
            }
            else if (r.ValueTextEquals("at"u8) || r.ValueTextEquals("from"u8) || r.ValueTextEquals("center"u8))
            {
                a = JsonFields.Vector(ref r, $"draw[{n}].{r.GetString()}");
            }
            else if (r.ValueTextEquals("to"u8))
            {
                b = JsonFields.Vector(ref r, $"draw[{n}].to");
            }
            else if (r.ValueTextEquals("radius"u8))
            {
                radius = JsonFields.Float(ref r, $"draw[{n}].radius");
            }
            else if (r.ValueTextEquals("text"u8))
            {
                text = JsonFields.Text(ref r, $"draw[{n}].text");
            }
            else if (r.ValueTextEquals("fish"u8))
            {
                fish = JsonFields.Int(ref r, $"draw[{n}].fish");
            }
            else if (r.ValueTextEquals("color"u8))
            {
                rgb = Color(JsonFields.Text(ref r, $"draw[{n}].color"), n);
            }
            else
            {
                JsonFields.Skip(ref r);
            }
        }

        var at = a ?? throw new ProtocolException($"draw[{n}]: a shape needs at, from or center");
        return kind switch
        {
            "point" => new DebugShape(DebugShapeKind.Point, fish, at, at, 0f, rgb, null),
            "line" => new DebugShape(DebugShapeKind.Line, fish, at, b ?? throw JsonFieldsMissing(n, "to"), 0f, rgb, null),
            "circle" => new DebugShape(DebugShapeKind.Circle, fish, at, at, radius, rgb, null),
            "text" => new DebugShape(DebugShapeKind.Text, fish, at, at, 0f, rgb, text ?? throw JsonFieldsMissing(n, "text")),
            _ => throw new ProtocolException($"draw[{n}].kind: expected point, line, circle or text, got {(kind is null ? "nothing" : "\"" + Cut(kind) + "\"")}"),
        };
    }

    private static ProtocolException JsonFieldsMissing(int n, string field) => new($"draw[{n}].{field}: missing");

    private static string Cut(string s) => s.Length <= 40 ? s : s[..40];

    private static int Color(string? text, int n)
    {
        if (text is { Length: 7 } && text[0] == '#'
            && int.TryParse(text.AsSpan(1), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out int rgb))
        {
            return rgb;
        }

        throw new ProtocolException($"draw[{n}].color: expected \"#rrggbb\", got {(text is null ? "null" : "\"" + Cut(text) + "\"")}");
    }

    private static void Pair(Utf8JsonWriter w, string name, Vector2 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X);
        w.WriteNumberValue(v.Y);
        w.WriteEndArray();
    }
}
