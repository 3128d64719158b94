using System.Numerics;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Simulation;

/// <summary>One ball: radius, position and velocity (mm, mm/s; X = world X, Y = world Z).</summary>
internal sealed class BallState(int index, float radius, Vector2 position, Vector2 velocity)
{
    /// <summary>Index (ballN).</summary>
    public int Index { get; } = index;

    /// <summary>Radius, mm.</summary>
    public float Radius { get; } = radius;

    /// <summary>Where the ball starts and is put back after a goal.</summary>
    public Vector2 StartPosition { get; } = position;

    /// <summary>Centre, mm.</summary>
    public Vector2 Position = position;

    /// <summary>Physical velocity, mm/s.</summary>
    public Vector2 Velocity = velocity;

    /// <summary>This cycle's noise drift, mm/s (added to the motion only, not to the physics).</summary>
    public Vector2 NoiseVelocity;

    /// <summary>
    /// True while a competition item keeps this ball out of play (potted, laid where the item says,
    /// possibly outside the pool): it does not move and collides with nothing.
    /// </summary>
    public bool OutOfPlay;

    /// <summary>The ball as a circle at its current position.</summary>
    public Circle Shape => new(Position, Radius);
}
