using System.Globalization;

namespace URWPGSim2D.Protocol;

/// <summary>
/// Reads a strategy's debug drawings from a <c>decisions</c> message's <c>draw</c> array, the form
/// <see cref="DebugShapeJson"/> writes (docs/protocol.md).
/// </summary>
internal static class DrawingReader
{
    /// <summary>
    /// Reads a <c>draw</c> array (the reader on its property name) into <paramref name="into"/>, which
    /// keeps what fits its bounds; a shape that is not one of the forms above throws <see cref="ProtocolException"/>.
    /// </summary>
    public static void ReadArray(ref Utf8JsonReader r, DebugRecorder into)
    {
        JsonFields.StartArray(ref r, "draw");
        int n = 0;
        while (JsonFields.NextObject(ref r, "draw", n))
        {
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
}
