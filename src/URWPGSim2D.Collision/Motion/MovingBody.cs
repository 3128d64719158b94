using URWPGSim2D.Collision.Pool;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// One body of a <see cref="TimeOfImpact"/> query: its shape at the start of the interval and its
/// rigid motion over it (velocity, and angular velocity about its origin for a polygon or a fish).
/// </summary>
public readonly struct MovingBody
{
    private MovingBody(BodyKind kind, Vector2 velocity, float angularVelocity)
    {
        Kind = kind;
        Velocity = velocity;
        AngularVelocity = angularVelocity;
    }

    /// <summary>What the body is.</summary>
    public BodyKind Kind { get; }

    /// <summary>Velocity, mm/s (zero for static bodies).</summary>
    public Vector2 Velocity { get; }

    /// <summary>Angular velocity, rad/s (zero for circles and static bodies).</summary>
    public float AngularVelocity { get; }

    internal Circle CircleShape { get; private init; }

    internal ConvexPolygon Outline { get; private init; }

    internal Vector2 Position { get; private init; }

    internal float Heading { get; private init; }

    internal FishModel? Model { get; private init; }

    internal Shape StaticShape { get; private init; }

    internal Field? Field { get; private init; }

    /// <summary>A circle moving with a velocity.</summary>
    /// <param name="shape">The circle at the start, mm.</param>
    /// <param name="velocity">Velocity, mm/s.</param>
    /// <returns>The body.</returns>
    public static MovingBody Circle(in Circle shape, Vector2 velocity) =>
        new(BodyKind.Circle, velocity, 0f) { CircleShape = shape };

    /// <summary>A convex polygon, given about its own origin, placed at a pose and moving and turning about that origin.</summary>
    /// <param name="outline">The outline about the origin, mm.</param>
    /// <param name="position">Where the origin is at the start, mm.</param>
    /// <param name="heading">How far the outline is turned at the start, rad.</param>
    /// <param name="velocity">Velocity, mm/s.</param>
    /// <param name="angularVelocity">Angular velocity, rad/s.</param>
    /// <returns>The body.</returns>
    public static MovingBody Polygon(in ConvexPolygon outline, Vector2 position, float heading, Vector2 velocity, float angularVelocity) =>
        new(BodyKind.Polygon, velocity, angularVelocity) { Outline = outline, Position = position, Heading = heading };

    /// <summary>A fish at its model's pose, moving and turning about its body centre; its joints keep their angles.</summary>
    /// <param name="model">The fish at the start (re-posed during the query and restored before it returns).</param>
    /// <param name="velocity">Velocity, mm/s.</param>
    /// <param name="angularVelocity">Angular velocity, rad/s.</param>
    /// <returns>The body.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="model"/> is null.</exception>
    public static MovingBody Fish(FishModel model, Vector2 velocity, float angularVelocity)
    {
        ArgumentNullException.ThrowIfNull(model);
        return new(BodyKind.Fish, velocity, angularVelocity) { Model = model };
    }

    /// <summary>A static shape (circle, box, 8-DOP, polygon or segment).</summary>
    /// <param name="shape">The shape, mm.</param>
    /// <returns>The body.</returns>
    public static MovingBody Static(in Shape shape) => new(BodyKind.Static, Vector2.Zero, 0f) { StaticShape = shape };

    /// <summary>The walls of a pool (the other body must stay inside its bounds).</summary>
    /// <param name="field">The pool.</param>
    /// <returns>The body.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="field"/> is null.</exception>
    public static MovingBody Walls(Field field)
    {
        ArgumentNullException.ThrowIfNull(field);
        return new(BodyKind.Walls, Vector2.Zero, 0f) { Field = field };
    }
}
