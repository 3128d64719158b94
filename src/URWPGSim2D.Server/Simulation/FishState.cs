using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Server.Simulation.Kinematics;
using URWPGSim2D.Server.Strategies;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// One fish: team, size, pose (position, heading, three joint angles), the speed and angular-speed
/// approach state, the decision it executes and its collision model. Within a cycle the stepper
/// moves it with <see cref="Velocity"/> (+ noise) and <see cref="AngularVelocity"/>; contacts may change
/// both; at the end of the cycle the forward speed is what remains along the heading.
/// </summary>
internal sealed class FishState
{
    public FishState(int index, int team, FishSize size, Vector2 position, float heading)
    {
        Index = index;
        Team = team;
        Size = size;
        Position = position;
        Heading = Angles.Wrap(heading);
        Model = new FishModel(size, new FishPose(position, Heading, 0f, 0f, 0f));
        BasePosition = position;
        BaseHeading = Heading;
        Decision = Decision.Stop;
        Turn.Reset(0f);
        Speed.Reset(0f);
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

    /// <summary>Forward speed along the heading, mm/s, and its one-tenth approach.</summary>
    public GearApproach Speed;

    /// <summary>Angular speed, rad/s, and its one-tenth approach.</summary>
    public GearApproach Turn;

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

    /// <summary>Whether a contact changed the velocity in this cycle.</summary>
    public bool Touched;

    /// <summary>Pose at the stepper's last committed time.</summary>
    public Vector2 BasePosition;

    /// <summary>Heading at the stepper's last committed time.</summary>
    public float BaseHeading;

    /// <summary>Forward unit vector u = (cos θ, sin θ).</summary>
    public Vector2 Forward => new(MathF.Cos(Heading), MathF.Sin(Heading));

    /// <summary>Thinnest feature of this fish: the end of tail segment 3 (2·0.089964·L3), mm.</summary>
    public float Thickness => MathF.Min(2f * 0.089964f * Size.Joint3, Size.Width);

    /// <summary>Distance along the axis from the centre to the head tip, mm.</summary>
    public float HeadReach => (Size.Length * 0.5f) + Size.Head;

    /// <summary>Rebuilds the collision model at the current position, heading and joints.</summary>
    public void SyncModel() => Model.SetPose(new FishPose(Position, Heading, Joint1, Joint2, Joint3));
}
