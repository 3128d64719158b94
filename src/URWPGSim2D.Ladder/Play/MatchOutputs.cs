using System.Collections.Generic;
using System.Text.Json;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder.Play;

/// <summary>
/// A match's outputs (its file <c>outputs.json</c>, kept with its record): per side as played, its
/// team's id, its slowest call (ms, null when not measured) and what its strategy printed
/// (<c>{"sides": [{"team", "slowestMs", "log"}, …]}</c>).
/// </summary>
internal static class MatchOutputs
{
    /// <summary>One side's outputs.</summary>
    public sealed record Side(long Team, double? SlowestMs, string Log);

    /// <summary>The file's text.</summary>
    public static string Json(IReadOnlyList<(long Team, double? SlowestMs, string Log)> sides) =>
        JsonText.Of(w =>
        {
            w.WriteStartObject();
            w.WriteStartArray("sides");
            foreach (var (team, slowest, log) in sides)
            {
                w.WriteStartObject();
                w.WriteNumber("team", team);
                if (slowest is { } ms)
                {
                    w.WriteNumber("slowestMs", System.Math.Round(ms, 1));
                }
                else
                {
                    w.WriteNull("slowestMs");
                }

                w.WriteString("log", log);
                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteEndObject();
        });

    /// <summary>The sides of a match's file, or null when there is none (the match is not played yet).</summary>
    public static IReadOnlyList<Side>? Read(byte[]? file)
    {
        if (file is null)
        {
            return null;
        }

        using var document = JsonDocument.Parse(file);
        var sides = new List<Side>();
        foreach (var s in document.RootElement.GetProperty("sides").EnumerateArray())
        {
            var slowest = s.GetProperty("slowestMs");
            sides.Add(new Side(s.GetProperty("team").GetInt64(), slowest.ValueKind == JsonValueKind.Number ? slowest.GetDouble() : null, s.GetProperty("log").GetString() ?? string.Empty));
        }

        return sides;
    }
}
