using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// A body that never moves: an obstacle (round: a circle; rectangle: a convex polygon) or a goal
/// block (an axis-aligned box). Static partners always keep their place in a collision.
/// </summary>
public sealed class StaticBody
{
    private StaticBody(int id, bool isGoalBlock, ShapeKind kind, Circle circle, ConvexPolygon polygon, Aabb box, Aabb bounds, float thickness)
    {
        Id = id;
        IsGoalBlock = isGoalBlock;
        Kind = kind;
        Circle = circle;
        Polygon = polygon;
        Box = box;
        Bounds = bounds;
        Thickness = thickness;
    }

    /// <summary>obstacleN or goalBlockN number.</summary>
    public int Id { get; }

    /// <summary>True for a goal block (part of the pool's border), false for an obstacle.</summary>
    public bool IsGoalBlock { get; }

    /// <summary>Which of <see cref="Circle"/>, <see cref="Polygon"/>, <see cref="Box"/> is the shape.</summary>
    public ShapeKind Kind { get; }

    /// <summary>Round obstacle shape.</summary>
    public Circle Circle { get; }

    /// <summary>Rectangle obstacle shape (any heading).</summary>
    public ConvexPolygon Polygon { get; }

    /// <summary>Goal block shape.</summary>
    public Aabb Box { get; }

    /// <summary>Axis-aligned bounds of the shape (broad phase).</summary>
    public Aabb Bounds { get; }

    /// <summary>Thinnest width of the shape, mm (sub-step sizing).</summary>
    public float Thickness { get; }

    /// <summary>A round obstacle.</summary>
    public static StaticBody Round(int id, Vector2 center, float radius) =>
        new(id, false, ShapeKind.Circle, new Circle(center, radius), default, default,
            new Aabb(center - new Vector2(radius), center + new Vector2(radius)), 2f * radius);

    /// <summary>A rectangle obstacle: centre, length along <paramref name="heading"/>, width across.</summary>
    public static StaticBody Rectangle(int id, Vector2 center, float length, float width, float heading)
    {
        Vector2 u = new(System.MathF.Cos(heading), System.MathF.Sin(heading));
        Vector2 n = new(-u.Y, u.X);
        Vector2 a = u * (length * 0.5f);
        Vector2 b = n * (width * 0.5f);
        System.Span<Vector2> corners = [center + a + b, center - a + b, center - a - b, center + a - b];
        Vector2 lo = Vector2.Min(Vector2.Min(corners[0], corners[1]), Vector2.Min(corners[2], corners[3]));
        Vector2 hi = Vector2.Max(Vector2.Max(corners[0], corners[1]), Vector2.Max(corners[2], corners[3]));
        return new StaticBody(id, false, ShapeKind.Polygon, default, new ConvexPolygon(corners), default, new Aabb(lo, hi), System.MathF.Min(length, width));
    }

    /// <summary>A goal block.</summary>
    public static StaticBody GoalBlock(int id, in Aabb box)
    {
        Vector2 size = box.Max - box.Min;
        return new StaticBody(id, true, ShapeKind.Aabb, default, default, box, box, System.MathF.Min(size.X, size.Y));
    }
}
