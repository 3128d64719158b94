using URWPGSim2D.Strategies;
using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.StrategyHelper;

/// <summary>
/// Debug drawings for strategies of the original API, made inside <c>GetDecision</c>: points, lines,
/// circles and texts in field millimetres (X and Z of the vectors; Y is ignored), for one of the team's
/// fish or for the team. The server records them in the trace when asked (<c>run --debug-draw</c>) and
/// the replay and live pages draw them as a layer per team. When they are not recorded every call
/// returns at once; test <see cref="IsOn"/> before building a text. Each team keeps at most 128 shapes
/// and 4,096 characters of text per cycle.
/// </summary>
public static class DebugDraw
{
    /// <summary>Whether drawings of the running call are recorded.</summary>
    public static bool IsOn => DebugRecorder.Current is not null;

    /// <summary>Draws a dot.</summary>
    /// <param name="atMm">Where, mm.</param>
    /// <param name="fish">The fish it belongs to, as in <c>mission.TeamsRef[teamId].Fishes[fish]</c>, or −1 for the team.</param>
    /// <param name="color">Colour, or <see cref="Color.Empty"/> (the default) for the team's colour.</param>
    public static void Point(Xna.Vector3 atMm, int fish = -1, Color color = default)
    {
        if (DebugRecorder.Current is { } r)
        {
            r.Add(DebugShapeKind.Point, r.FishOfOrdinal(fish), new(atMm.X, atMm.Z), new(atMm.X, atMm.Z), 0f, Rgb(color), null);
        }
    }

    /// <summary>Draws a segment.</summary>
    /// <param name="fromMm">Start, mm.</param>
    /// <param name="toMm">End, mm.</param>
    /// <param name="fish">The fish it belongs to, as in <c>mission.TeamsRef[teamId].Fishes[fish]</c>, or −1 for the team.</param>
    /// <param name="color">Colour, or <see cref="Color.Empty"/> (the default) for the team's colour.</param>
    public static void Line(Xna.Vector3 fromMm, Xna.Vector3 toMm, int fish = -1, Color color = default)
    {
        if (DebugRecorder.Current is { } r)
        {
            r.Add(DebugShapeKind.Line, r.FishOfOrdinal(fish), new(fromMm.X, fromMm.Z), new(toMm.X, toMm.Z), 0f, Rgb(color), null);
        }
    }

    /// <summary>Draws a circle.</summary>
    /// <param name="centerMm">Centre, mm.</param>
    /// <param name="radiusMm">Radius, mm.</param>
    /// <param name="fish">The fish it belongs to, as in <c>mission.TeamsRef[teamId].Fishes[fish]</c>, or −1 for the team.</param>
    /// <param name="color">Colour, or <see cref="Color.Empty"/> (the default) for the team's colour.</param>
    public static void Circle(Xna.Vector3 centerMm, float radiusMm, int fish = -1, Color color = default)
    {
        if (DebugRecorder.Current is { } r)
        {
            r.Add(DebugShapeKind.Circle, r.FishOfOrdinal(fish), new(centerMm.X, centerMm.Z), new(centerMm.X, centerMm.Z), radiusMm, Rgb(color), null);
        }
    }

    /// <summary>Writes a text (a null text writes nothing).</summary>
    /// <param name="atMm">Where the text starts, mm.</param>
    /// <param name="text">The text (one line).</param>
    /// <param name="fish">The fish it belongs to, as in <c>mission.TeamsRef[teamId].Fishes[fish]</c>, or −1 for the team.</param>
    /// <param name="color">Colour, or <see cref="Color.Empty"/> (the default) for the team's colour.</param>
    public static void Text(Xna.Vector3 atMm, string? text, int fish = -1, Color color = default)
    {
        if (text is not null && DebugRecorder.Current is { } r)
        {
            r.Add(DebugShapeKind.Text, r.FishOfOrdinal(fish), new(atMm.X, atMm.Z), new(atMm.X, atMm.Z), 0f, Rgb(color), text);
        }
    }

    private static int Rgb(Color color) => color.IsEmpty ? -1 : color.ToArgb() & 0xFFFFFF;
}
