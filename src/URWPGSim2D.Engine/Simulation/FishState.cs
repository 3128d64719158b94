using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// One fish's game state: team, size, the decision it executes, its speed and turn gears, its
/// tail-wave phase, its corrections this cycle and whether its move was rejected. Its body — pose, joints, shape,
/// velocity, noise drift, whether it collides — is the motion world's (<see cref="MotionWorld"/>),
/// reached by <see cref="Handle"/>: the properties of those read and write it there, so there is
/// one copy. Within a cycle the motion world moves it with
/// <see cref="Velocity"/> (+ noise) and <see cref="AngularVelocity"/>; contacts may change both
/// for the rest of the cycle (the swimming speed and turn rate are not changed by contacts).
/// </summary>
public sealed class FishState
{
    private readonly MotionWorld _motion;

    /// <summary>Adds the fish's body to the motion world (joints straight) and sets up its game state.</summary>
    public FishState(MotionWorld motion, int index, int team, FishSize size, Vector2 position, float heading)
    {
        _motion = motion;
        Index = index;
        Team = team;
        Size = size;
        Handle = motion.AddFish(size, new FishPose(position, Angle.Wrap(heading), 0f, 0f, 0f));
        motion.SetTag(Handle, BodyTag.Fish(index));
        Decision = Decision.Stop;
        Turn.Reset(0f, TurnTable.Rates);
        Speed.Reset(0f, SpeedTable.Speeds);
    }

    /// <summary>Index (fishN).</summary>
    public int Index { get; }

    /// <summary>The fish's body in the motion world.</summary>
    public BodyId Handle { get; }

    /// <summary>Team 0 or 1.</summary>
    public int Team { get; }

    /// <summary>Body and tail sizes.</summary>
    public FishSize Size { get; }

    /// <summary>Centre of the body rectangle, mm (the motion world's; setting it places the body there).</summary>
    public Vector2 Position
    {
        get => _motion.PositionOf(Handle);
        set
        {
            if (value != _motion.PositionOf(Handle))
            {
                _motion.SetPose(Handle, value, _motion.HeadingOf(Handle));
            }
        }
    }

    /// <summary>Heading, rad, wrapped to [−π, π) (the motion world's; setting it turns the body).</summary>
    public float Heading
    {
        get => _motion.HeadingOf(Handle);
        set
        {
            if (value != _motion.HeadingOf(Handle))
            {
                _motion.SetPose(Handle, _motion.PositionOf(Handle), value);
            }
        }
    }

    /// <summary>The body's pose and joint angles now, as the motion world holds them.</summary>
    public FishPose Pose => _motion.FishPoseOf(Handle);

    /// <summary>Joint angle φ1 from the body axis, rad (fixed for the whole cycle).</summary>
    public float Joint1 => Pose.Joint1;

    /// <summary>Joint angle φ2, rad.</summary>
    public float Joint2 => Pose.Joint2;

    /// <summary>Joint angle φ3, rad.</summary>
    public float Joint3 => Pose.Joint3;

    /// <summary>Forward speed along the heading, mm/s, and its gear approach state (never changed by a contact).</summary>
    public GearApproach Speed;

    /// <summary>Angular speed, rad/s, and its gear approach state (never changed by a contact).</summary>
    public GearApproach Turn;

    /// <summary>The fish's own tail-wave phase p, radians (0 unless set).</summary>
    public float TailPhase;

    /// <summary>The decision being executed.</summary>
    public Decision Decision;

    /// <summary>Physical velocity inside the current cycle, mm/s (the motion world's own velocity of the body).</summary>
    public Vector2 Velocity
    {
        get => _motion.VelocityOf(Handle);
        set => _motion.SetVelocity(Handle, value, _motion.AngularVelocityOf(Handle));
    }

    /// <summary>Angular velocity inside the current cycle, rad/s (includes collision spin).</summary>
    public float AngularVelocity
    {
        get => _motion.AngularVelocityOf(Handle);
        set => _motion.SetVelocity(Handle, _motion.VelocityOf(Handle), value);
    }

    /// <summary>This cycle's noise drift of position, mm/s (the body's drift in the motion world: it moves the fish, it is not its velocity).</summary>
    public Vector2 NoiseVelocity
    {
        get => _motion.DriftOf(Handle);
        set => _motion.SetDrift(Handle, value, _motion.AngularDriftOf(Handle));
    }

    /// <summary>This cycle's heading noise as a rate, rad/s (the body's turning drift).</summary>
    public float NoiseAngularVelocity
    {
        get => _motion.AngularDriftOf(Handle);
        set => _motion.SetDrift(Handle, _motion.DriftOf(Handle), value);
    }

    /// <summary>
    /// True when this cycle's move was rejected (by the motion world, or by the response through
    /// <see cref="MotionWorld.RejectMove"/>): the fish is back where it started the cycle and holds still
    /// (it counts as immovable in contacts) for the rest of the cycle. The motion world's
    /// <see cref="MotionWorld.WasRejected"/>, read through the fish's handle.
    /// </summary>
    public bool MoveRejected => _motion.WasRejected(Handle);

    /// <summary>
    /// True while a competition item keeps this fish out of play (frozen or caught, parked where the
    /// item says, possibly outside the pool): it does not move and collides with nothing (its body
    /// takes no part in the motion world's contacts).
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

    /// <summary>Forward unit vector u = (cos θ, sin θ).</summary>
    public Vector2 Forward
    {
        get
        {
            float heading = Heading;
            return new(MathF.Cos(heading), MathF.Sin(heading));
        }
    }

    /// <summary>Distance along the axis from the centre to the head tip, mm.</summary>
    public float HeadReach => (Size.Length * 0.5f) + Size.Head;

    /// <summary>
    /// Sets the cycle's motion at once: <see cref="Velocity"/>, <see cref="AngularVelocity"/>,
    /// <see cref="NoiseVelocity"/> and <see cref="NoiseAngularVelocity"/> (what setting the four
    /// properties one after another leaves).
    /// </summary>
    internal void SetMotion(Vector2 velocity, float angularVelocity, Vector2 noiseVelocity, float noiseAngularVelocity)
    {
        _motion.SetVelocity(Handle, velocity, angularVelocity);
        _motion.SetDrift(Handle, noiseVelocity, noiseAngularVelocity);
    }

    /// <summary>Sets the joint angles for the cycle (the body's shape changes only when they differ).</summary>
    public void SetJoints(float joint1, float joint2, float joint3)
    {
        if (!HasJoints(joint1, joint2, joint3))
        {
            _motion.SetJoints(Handle, joint1, joint2, joint3);
        }
    }

    /// <summary>Sets the angles the joints turn to over the next cycle, swept like any motion (<see cref="MotionWorld.SetJointTargets"/>); nothing when they are those already.</summary>
    internal void TurnJoints(float joint1, float joint2, float joint3)
    {
        if (!HasJoints(joint1, joint2, joint3))
        {
            _motion.SetJointTargets(Handle, joint1, joint2, joint3);
        }
    }

    // Whether the joints have these angles now, bit for bit.
    private bool HasJoints(float joint1, float joint2, float joint3)
    {
        FishPose pose = Pose;
        return pose.Joint1 == joint1 && pose.Joint2 == joint2 && pose.Joint3 == joint3;
    }

    /// <summary>Back to the state a fish made at <paramref name="position"/> and <paramref name="heading"/> has: joints straight, at rest, in play, no decision yet.</summary>
    internal void Restart(Vector2 position, float heading, float tailPhase)
    {
        _motion.SetPose(Handle, position, Angle.Wrap(heading));
        _motion.SetJoints(Handle, 0f, 0f, 0f);
        SetMotion(Vector2.Zero, 0f, Vector2.Zero, 0f);
        OutOfPlay = false;
        Decision = Decision.Stop;
        Turn.Reset(0f, TurnTable.Rates);
        Speed.Reset(0f, SpeedTable.Speeds);
        TailPhase = tailPhase;
    }
}
