using System.Numerics;

namespace URWPGSim2D.Server.Items;

/// <summary>The shape of an <see cref="ItemZone"/>.</summary>
internal enum ZoneShape
{
    /// <summary>A circle: <see cref="ItemZone.Center"/>, <see cref="ItemZone.Radius"/>.</summary>
    Circle,

    /// <summary>An axis-aligned box: <see cref="ItemZone.Min"/>, <see cref="ItemZone.Max"/>.</summary>
    Box,
}

/// <summary>
/// A marked region of an item's field that is not a body: a goal box, a target hole, a parking
/// place. Written to the trace's cycle-0 layout (<c>zones</c>) and drawn in figures.
/// </summary>
/// <param name="Kind">goal-box, hole, target, rescue, forbidden, start, parking, …</param>
/// <param name="Id">Number within its kind (e.g. the hole of ball i is hole i).</param>
/// <param name="Team">The team it belongs to at the start of the match, or −1.</param>
/// <param name="Shape">Circle or box.</param>
/// <param name="Center">Circle centre, mm.</param>
/// <param name="Radius">Circle radius, mm.</param>
/// <param name="Min">Box corner with the smallest x and z, mm.</param>
/// <param name="Max">Box corner with the largest x and z, mm.</param>
internal readonly record struct ItemZone(string Kind, int Id, int Team, ZoneShape Shape, Vector2 Center, float Radius, Vector2 Min, Vector2 Max)
{
    /// <summary>A circular zone.</summary>
    public static ItemZone Circle(string kind, int id, int team, Vector2 center, float radius) =>
        new(kind, id, team, ZoneShape.Circle, center, radius, center - new Vector2(radius), center + new Vector2(radius));

    /// <summary>A box zone.</summary>
    public static ItemZone Box(string kind, int id, int team, Vector2 min, Vector2 max) =>
        new(kind, id, team, ZoneShape.Box, (min + max) * 0.5f, 0f, min, max);
}
