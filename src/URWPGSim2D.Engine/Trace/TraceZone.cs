namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// A static zone of an item in the trace's <c>layout.zones</c>: a kind (<c>hole</c>, <c>target</c>,
/// <c>rescue</c>, <c>forbidden</c>, <c>goal-box</c>, <c>start</c>, …), an id, an optional team and
/// one shape — a circle, an axis-aligned box or a polygon (mm; X = world X, Y = world Z).
/// Create one with <see cref="Circle"/>, <see cref="Box"/> or <see cref="Polygon"/>.
/// </summary>
public sealed class TraceZone
{
    private TraceZone(string kind, int id, int? team, TraceZoneShape shape, Vector2 center, float radius, Vector2 min, Vector2 max, Vector2[] points)
    {
        ArgumentException.ThrowIfNullOrEmpty(kind);
        Kind = kind;
        Id = id;
        Team = team;
        Shape = shape;
        Center = center;
        Radius = radius;
        Min = min;
        Max = max;
        Points = points;
    }

    /// <summary>Zone kind.</summary>
    public string Kind { get; }

    /// <summary>Zone id (unique within its kind).</summary>
    public int Id { get; }

    /// <summary>The team it belongs to, or null.</summary>
    public int? Team { get; }

    /// <summary>Which of the shape members is meaningful.</summary>
    public TraceZoneShape Shape { get; }

    /// <summary>Circle centre, mm.</summary>
    public Vector2 Center { get; }

    /// <summary>Circle radius, mm.</summary>
    public float Radius { get; }

    /// <summary>Box corner with the smallest coordinates, mm.</summary>
    public Vector2 Min { get; }

    /// <summary>Box corner with the largest coordinates, mm.</summary>
    public Vector2 Max { get; }

    /// <summary>Polygon vertices, mm (empty unless a polygon).</summary>
    public Vector2[] Points { get; }

    /// <summary>A circular zone.</summary>
    public static TraceZone Circle(string kind, int id, Vector2 center, float radius, int? team = null) =>
        new(kind, id, team, TraceZoneShape.Circle, center, radius, default, default, []);

    /// <summary>An axis-aligned box zone.</summary>
    public static TraceZone Box(string kind, int id, Vector2 min, Vector2 max, int? team = null) =>
        new(kind, id, team, TraceZoneShape.Box, default, 0f, min, max, []);

    /// <summary>A polygon zone (at least three vertices).</summary>
    public static TraceZone Polygon(string kind, int id, Vector2[] points, int? team = null)
    {
        ArgumentNullException.ThrowIfNull(points);
        if (points.Length < 3)
        {
            throw new ArgumentException($"a polygon zone needs at least 3 vertices, got {points.Length}", nameof(points));
        }

        return new(kind, id, team, TraceZoneShape.Polygon, default, 0f, default, default, (Vector2[])points.Clone());
    }
}

/// <summary>The shape of a <see cref="TraceZone"/>.</summary>
public enum TraceZoneShape
{
    /// <summary>Centre and radius.</summary>
    Circle,

    /// <summary>Axis-aligned box.</summary>
    Box,

    /// <summary>Polygon.</summary>
    Polygon,
}
