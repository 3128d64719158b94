using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Server.Simulation.Kinematics;
using URWPGSim2D.Server.Hosting;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// One fish: team, size, pose (position, heading, three joint angles), the speed and angular-speed
/// approach state, the decision it executes and its collision model. Within a cycle the stepper
/// moves it with <see cref="Velocity"/> (+ noise) and <see cref="AngularVelocity"/>; contacts may change
/// both for the rest of the cycle (the swimming speed and turn rate are not changed by contacts).
/// </summary>
internal sealed class FishState
{
    private bool _modelStale;

    public FishState(int index, int team, FishSize size, Vector2 position, float heading)
    {
        Index = index;
        Team = team;
        Size = size;
        Position = position;
        Heading = Angle.Wrap(heading);
        Model = new FishModel(size, new FishPose(position, Heading, 0f, 0f, 0f));
        Decision = Decision.Stop;
        Turn.Reset(0f, TurnTable.Rates);
        Speed.Reset(0f, SpeedTable.Speeds);
    }

    /// <summary>Index (fishN).</summary>
    public int Index { get; }

    /// <summary>Team 0 or 1.</summary>
    public int Team { get; }

    /// <summary>Body and tail sizes.</summary>
    public FishSize Size { get; }

    /// <summary>Collision model, kept at the current pose.</summary>
    public FishModel Model { get; }

    /// <summary>Centre of the body rectangle, mm.</summary>
    public Vector2 Position;

    /// <summary>Heading, rad, wrapped to [−π, π).</summary>
    public float Heading;

    /// <summary>Joint angles φ1..φ3 from the body axis, rad (fixed for the whole cycle).</summary>
    public float Joint1, Joint2, Joint3;

    /// <summary>Forward speed along the heading, mm/s, and its gear approach state (never changed by a contact).</summary>
    public GearApproach Speed;

    /// <summary>Angular speed, rad/s, and its gear approach state (never changed by a contact).</summary>
    public GearApproach Turn;

    /// <summary>The fish's own tail-wave phase p, radians (0 unless set).</summary>
    public float TailPhase;

    /// <summary>The decision being executed.</summary>
    public Decision Decision;

    /// <summary>Physical velocity inside the current cycle, mm/s.</summary>
    public Vector2 Velocity;

    /// <summary>Angular velocity inside the current cycle, rad/s (includes collision spin).</summary>
    public float AngularVelocity;

    /// <summary>This cycle's noise drift of position (mm/s) and heading (rad/s).</summary>
    public Vector2 NoiseVelocity;

    /// <summary>This cycle's heading noise as a rate, rad/s.</summary>
    public float NoiseAngularVelocity;

    /// <summary>Pose at the start of the cycle (the last cycle's resolved end), restored by <see cref="Freeze"/>.</summary>
    public Vector2 StartPosition;

    /// <summary>Heading at the start of the cycle.</summary>
    public float StartHeading;

    /// <summary>Joint angles at the start of the cycle.</summary>
    public float StartJoint1, StartJoint2, StartJoint3;

    /// <summary>Position corrections this fish has had in the current cycle.</summary>
    public int Corrections;

    /// <summary>
    /// True when this cycle's move was rejected: the fish is back at its start pose and holds still
    /// (it counts as immovable in contacts) for the rest of the cycle.
    /// </summary>
    public bool Frozen;

    /// <summary>
    /// True while a competition item keeps this fish out of play (frozen or caught, parked where the
    /// item says, possibly outside the pool): it does not move and collides with nothing.
    /// </summary>
    public bool OutOfPlay;

    /// <summary>Forward unit vector u = (cos θ, sin θ).</summary>
    public Vector2 Forward => new(MathF.Cos(Heading), MathF.Sin(Heading));

    /// <summary>Distance along the axis from the centre to the head tip, mm.</summary>
    public float HeadReach => (Size.Length * 0.5f) + Size.Head;

    /// <summary>Remembers the current pose as the cycle's start pose and clears the per-cycle flags.</summary>
    public void BeginCycle()
    {
        StartPosition = Position;
        StartHeading = Heading;
        StartJoint1 = Joint1;
        StartJoint2 = Joint2;
        StartJoint3 = Joint3;
        Corrections = 0;
        Frozen = false;
    }

    /// <summary>
    /// Rejects this cycle's move: back to the start pose (position, heading and joints), no motion
    /// for the rest of the cycle. Used when contacts cannot be resolved by moving the fish (it is
    /// wedged, e.g. its tail pose does not fit between two walls).
    /// </summary>
    public void Freeze()
    {
        Position = StartPosition;
        Heading = StartHeading;
        Joint1 = StartJoint1;
        Joint2 = StartJoint2;
        Joint3 = StartJoint3;
        Velocity = Vector2.Zero;
        AngularVelocity = 0f;
        NoiseVelocity = Vector2.Zero;
        NoiseAngularVelocity = 0f;
        Frozen = true;
        Invalidate();
    }

    /// <summary>The collision model exactly at the current pose and joints (rebuilt first when it lags behind).</summary>
    public FishModel PosedModel
    {
        get
        {
            FishPose posed = Model.Pose;
            if (_modelStale || posed.Position != Position || posed.Heading != Heading
                || posed.Joint1 != Joint1 || posed.Joint2 != Joint2 || posed.Joint3 != Joint3)
            {
                SyncModel();
            }

            return Model;
        }
    }

    /// <summary>Rebuilds the collision model at the current position, heading and joints.</summary>
    public void SyncModel()
    {
        Model.SetPose(new FishPose(Position, Heading, Joint1, Joint2, Joint3));
        _modelStale = false;
    }

    /// <summary>Marks the pose fields as changed; the model is rebuilt when next needed.</summary>
    public void Invalidate() => _modelStale = true;
}
