using System.Collections.Generic;
using System.IO;
using System.Text.Json;
using URWPGSim2D.Ladder.Storage;
using URWPGSim2D.Tournament.Batch;

namespace URWPGSim2D.Ladder.Play;

/// <summary>
/// A match's outputs file, <c>outputs/match-ID.json</c>: per side as played, its team's id, its
/// slowest call (ms, null when not measured) and what its strategy printed
/// (<c>{"sides": [{"team", "slowestMs", "log"}, …]}</c>). Written whole before the match's record,
/// so a match played again writes it again.
/// </summary>
internal static class MatchOutputs
{
    /// <summary>One side's outputs.</summary>
    public sealed record Side(long Team, double? SlowestMs, string Log);

    /// <summary>Writes the file (whole or not at all).</summary>
    public static void Write(string path, IReadOnlyList<(long Team, double? SlowestMs, string Log)> sides) =>
        AtomicFile.WriteAllText(path, JsonText.Of(w =>
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
        }));

    /// <summary>The sides of a match's file, or null when there is none (the match is not played yet).</summary>
    public static IReadOnlyList<Side>? Read(string path)
    {
        if (!File.Exists(path))
        {
            return null;
        }

        using var document = JsonDocument.Parse(File.ReadAllText(path));
        var sides = new List<Side>();
        foreach (var s in document.RootElement.GetProperty("sides").EnumerateArray())
        {
            var slowest = s.GetProperty("slowestMs");
            sides.Add(new Side(s.GetProperty("team").GetInt64(), slowest.ValueKind == JsonValueKind.Number ? slowest.GetDouble() : null, s.GetProperty("log").GetString() ?? string.Empty));
        }

        return sides;
    }
}
