using System.Globalization;
using System.Text.Json;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Strategies;

/// <summary>
/// A strategy's debug drawing as JSON, the same in a <c>decisions</c> message's <c>draw</c> array and in
/// a trace line's <c>draw</c> array (docs/protocol.md, docs/viewer.md):
/// <c>{"kind":"line","fish":1,"from":[x,y],"to":[x,y],"color":"#rrggbb"}</c>; a point and a text have
/// <c>at</c> (a text also <c>text</c>), a circle <c>center</c> and <c>radius</c>. <c>fish</c> and
/// <c>color</c> are left out for the team's drawings in the team's colour.
/// </summary>
public static class DebugShapeJson
{
    /// <summary>Writes <paramref name="s"/> as one object (with <c>team</c> first when given).</summary>
    /// <param name="w">Where to write.</param>
    /// <param name="s">The shape.</param>
    /// <param name="team">The team that drew it, or −1 to leave <c>team</c> out.</param>
    public static void Write(Utf8JsonWriter w, in DebugShape s, int team = -1)
    {
        ArgumentNullException.ThrowIfNull(w);
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
    /// <param name="w">Where to write.</param>
    /// <param name="drawings">The recorder whose shapes to write.</param>
    public static void WriteArray(Utf8JsonWriter w, DebugRecorder drawings)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(drawings);
        w.WriteStartArray("draw");
        foreach (ref readonly var s in drawings.Shapes)
        {
            Write(w, s);
        }

        w.WriteEndArray();
    }

    private static void Pair(Utf8JsonWriter w, string name, Vector2 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X);
        w.WriteNumberValue(v.Y);
        w.WriteEndArray();
    }
}
