namespace URWPGSim2D.Strategies;

/// <summary>
/// Debug drawings a strategy makes while it decides: points, lines, circles and texts in field
/// coordinates (mm, X = world X, Y = world Z), for one of its fish or for the team. The server records
/// them in that cycle's trace line when asked (<c>run --debug-draw</c>) and the replay and live pages
/// draw them as a layer per team. When they are not recorded every call returns at once and allocates
/// nothing; test <see cref="IsOn"/> before building a text. Each team keeps at most 128 shapes and
/// 4,096 characters of text per cycle; more is dropped. Call them from <see cref="IStrategy.Decide"/>'s
/// thread (drawings from other threads are not recorded).
/// </summary>
public static class DebugDraw
{
    /// <summary>Whether drawings of the running call are recorded.</summary>
    public static bool IsOn => DebugRecorder.Current is not null;

    /// <summary>Draws a dot.</summary>
    /// <param name="at">Where, mm.</param>
    /// <param name="fish">The fish it belongs to (index into <see cref="MatchSnapshot.Fish"/>, one the strategy controls), or −1 for the team.</param>
    /// <param name="rgb">Colour 0xRRGGBB, or −1 for the team's colour.</param>
    public static void Point(Vector2 at, int fish = -1, int rgb = -1) =>
        DebugRecorder.Current?.Add(DebugShapeKind.Point, fish, at, at, 0f, rgb, null);

    /// <summary>Draws a segment.</summary>
    /// <param name="from">Start, mm.</param>
    /// <param name="to">End, mm.</param>
    /// <param name="fish">The fish it belongs to (index into <see cref="MatchSnapshot.Fish"/>, one the strategy controls), or −1 for the team.</param>
    /// <param name="rgb">Colour 0xRRGGBB, or −1 for the team's colour.</param>
    public static void Line(Vector2 from, Vector2 to, int fish = -1, int rgb = -1) =>
        DebugRecorder.Current?.Add(DebugShapeKind.Line, fish, from, to, 0f, rgb, null);

    /// <summary>Draws a circle.</summary>
    /// <param name="center">Centre, mm.</param>
    /// <param name="radius">Radius, mm.</param>
    /// <param name="fish">The fish it belongs to (index into <see cref="MatchSnapshot.Fish"/>, one the strategy controls), or −1 for the team.</param>
    /// <param name="rgb">Colour 0xRRGGBB, or −1 for the team's colour.</param>
    public static void Circle(Vector2 center, float radius, int fish = -1, int rgb = -1) =>
        DebugRecorder.Current?.Add(DebugShapeKind.Circle, fish, center, center, radius, rgb, null);

    /// <summary>Writes a text (a null text writes nothing).</summary>
    /// <param name="at">Where the text starts, mm.</param>
    /// <param name="text">The text (one line; what is over the cycle's 4,096 characters is cut).</param>
    /// <param name="fish">The fish it belongs to (index into <see cref="MatchSnapshot.Fish"/>, one the strategy controls), or −1 for the team.</param>
    /// <param name="rgb">Colour 0xRRGGBB, or −1 for the team's colour.</param>
    public static void Text(Vector2 at, string? text, int fish = -1, int rgb = -1)
    {
        if (text is not null)
        {
            DebugRecorder.Current?.Add(DebugShapeKind.Text, fish, at, at, 0f, rgb, text);
        }
    }
}
