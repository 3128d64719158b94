using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// One ball's game state: its start (where it is put back after a goal) (mm; X = world X, Y =
/// world Z). Its body — radius, position, velocity, noise drift, whether it collides — is the
/// motion world's (<see cref="MotionWorld"/>), reached by <see cref="Handle"/>.
/// </summary>
public sealed class BallState
{
    private readonly MotionWorld _motion;

    /// <summary>Adds the ball's body to the motion world and sets up its game state.</summary>
    public BallState(MotionWorld motion, int index, float radius, Vector2 position, Vector2 velocity)
    {
        _motion = motion;
        Index = index;
        Radius = radius;
        StartPosition = position;
        Handle = motion.AddCircle(radius, position);
        motion.SetTag(Handle, BodyTag.Ball(index));
        Velocity = velocity;
    }

    /// <summary>Index (ballN).</summary>
    public int Index { get; }

    /// <summary>The ball's body in the motion world.</summary>
    public BodyId Handle { get; }

    /// <summary>Radius, mm.</summary>
    public float Radius { get; }

    /// <summary>Where the ball starts and is put back after a goal.</summary>
    public Vector2 StartPosition { get; }

    /// <summary>Centre, mm (the motion world's; setting it places the body there).</summary>
    public Vector2 Position
    {
        get => _motion.PositionOf(Handle);
        set
        {
            if (value != _motion.PositionOf(Handle))
            {
                _motion.SetPose(Handle, value, 0f);
            }
        }
    }

    /// <summary>Physical velocity, mm/s (the motion world's own velocity of the body).</summary>
    public Vector2 Velocity
    {
        get => _motion.VelocityOf(Handle);
        set => _motion.SetVelocity(Handle, value);
    }

    /// <summary>This cycle's noise drift, mm/s (the body's drift in the motion world: it moves the ball, it is not its velocity).</summary>
    public Vector2 NoiseVelocity
    {
        get => _motion.DriftOf(Handle);
        set => _motion.SetDrift(Handle, value);
    }

    /// <summary>
    /// True while a competition item keeps this ball out of play (potted, laid where the item says,
    /// possibly outside the pool): it does not move and collides with nothing (its body takes no
    /// part in the motion world's contacts).
    /// </summary>
    public bool OutOfPlay
    {
        get => !_motion.CollidesOf(Handle);
        set
        {
            if (_motion.CollidesOf(Handle) == value)
            {
                _motion.SetCollides(Handle, !value);
            }
        }
    }

    /// <summary>The ball as a circle at its current position.</summary>
    public Circle Shape => new(Position, Radius);

    /// <summary>Back to the state the ball was made with: at its start position with <paramref name="velocity"/>, no drift, in play.</summary>
    internal void Restart(Vector2 velocity)
    {
        _motion.SetPose(Handle, StartPosition, 0f);
        _motion.SetVelocity(Handle, velocity);
        _motion.SetDrift(Handle, Vector2.Zero);
        OutOfPlay = false;
    }
}
