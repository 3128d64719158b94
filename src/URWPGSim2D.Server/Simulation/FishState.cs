using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Server.Simulation.Kinematics;
using URWPGSim2D.Server.Strategies;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// One fish: team, size, pose (position, heading, three joint angles), the speed and angular-speed
/// approach state, the decision it executes and its collision model. Within a cycle the stepper
/// moves it with <see cref="Velocity"/> (+ noise) and <see cref="AngularVelocity"/>; contacts may change
/// both for the rest of the cycle (the swimming speed and turn rate are not changed by contacts).
/// </summary>
internal sealed class FishState
{
    // Reference half-widths of tail segments 1 and 2 at their start (fractions of their lengths),
    // and how far the caudal fin reaches from tail segment 3's axis, mm.
    private const float TailStartHalfWidth1 = 0.266112f;
    private const float TailStartHalfWidth2 = 0.231336f;
    private const float CaudalReach = 50f;

    private readonly Vector2 _bodyGroupLocal;
    private readonly float _bodyGroupRadius;
    private RigidFrame _frame;
    private bool _frameValid;
    private Disc _bodyDisc;
    private Disc _tailDisc;
    private bool _groupsValid;

    public FishState(int index, int team, FishSize size, Vector2 position, float heading)
    {
        Index = index;
        Team = team;
        Size = size;
        Position = position;
        Heading = Angles.Wrap(heading);
        Model = new FishModel(size, new FishPose(position, Heading, 0f, 0f, 0f));
        Circle group = Model.BodyGroup;
        var (sin, cos) = MathF.SinCos(Heading);
        Vector2 offset = group.Center - position;
        _bodyGroupLocal = new Vector2((offset.X * cos) + (offset.Y * sin), (-offset.X * sin) + (offset.Y * cos));
        _bodyGroupRadius = group.Radius;
        BasePosition = position;
        BaseHeading = Heading;
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

    /// <summary>Pose at the stepper's last committed time.</summary>
    public Vector2 BasePosition;

    /// <summary>Heading at the stepper's last committed time.</summary>
    public float BaseHeading;

    /// <summary>The stepper's last committed time for this fish (cycle fraction 0 … 1).</summary>
    public double BaseTime;

    /// <summary>Forward unit vector u = (cos θ, sin θ).</summary>
    public Vector2 Forward => new(MathF.Cos(Heading), MathF.Sin(Heading));

    /// <summary>Thinnest feature of this fish: the end of tail segment 3 (2·0.089964·L3), mm.</summary>
    public float Thickness => MathF.Min(2f * 0.089964f * Size.Joint3, Size.Width);

    /// <summary>
    /// Farthest any point of the fish can be from its centre at any joint angles, mm: the tail chain
    /// plus the caudal fin (tips 2·L3 back along segment 3 and 50 mm aside), or the head or a pectoral fin tip.
    /// </summary>
    public float MaxReach => MathF.Max(HeadReach, (Size.Length * 0.5f) + Size.Joint1 + Size.Joint2 + (2f * Size.Joint3) + 50f) + 1f;

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

    /// <summary>Whether <see cref="Model"/> lags behind the pose fields (it is rebuilt only when a test needs it).</summary>
    public bool ModelStale { get; private set; }

    /// <summary>The collision model exactly at the current pose (rebuilt first if it lags behind).</summary>
    public FishModel PosedModel
    {
        get
        {
            if (ModelStale && !(JointsCurrent && Frame.IsIdentity))
            {
                SyncModel();
            }

            return Model;
        }
    }

    /// <summary>
    /// The collision model with the current joint angles, rebuilt only when they changed: it may
    /// sit at an older position and heading, related to the fish by <see cref="Frame"/>.
    /// </summary>
    public FishModel RigidModel
    {
        get
        {
            if (!JointsCurrent)
            {
                SyncModel();
            }

            return Model;
        }
    }

    /// <summary>The rigid motion from <see cref="Model"/>'s pose to the fish's current position and heading.</summary>
    public RigidFrame Frame
    {
        get
        {
            if (!_frameValid)
            {
                FishPose posed = Model.Pose;
                _frame = new RigidFrame(posed.Position, posed.Heading, Position, Heading);
                _frameValid = true;
            }

            return _frame;
        }
    }

    /// <summary>Whether the model was built with the current joint angles.</summary>
    public bool JointsCurrent
    {
        get
        {
            FishPose posed = Model.Pose;
            return posed.Joint1 == Joint1 && posed.Joint2 == Joint2 && posed.Joint3 == Joint3;
        }
    }

    private static Vector2 Direction(float angle)
    {
        var (sin, cos) = MathF.SinCos(angle);
        return new Vector2(cos, sin);
    }

    // The smallest circle holding both circles.
    private static Circle Enclosing(in Disc a, in Disc b)
    {
        float d = Vector2.Distance(a.Center, b.Center);
        if (d + b.Radius <= a.Radius)
        {
            return new Circle(a.Center, a.Radius);
        }

        if (d + a.Radius <= b.Radius)
        {
            return new Circle(b.Center, b.Radius);
        }

        float r = 0.5f * (d + a.Radius + b.Radius);
        Vector2 c = a.Center + ((b.Center - a.Center) * ((r - a.Radius) / d));
        return new Circle(c, r + 0.01f);
    }

    /// <summary>Rebuilds the collision model at the current position, heading and joints.</summary>
    public void SyncModel() => SyncModelAt(Position, Heading);

    /// <summary>
    /// Rebuilds the collision model with the current joints at the given position and heading (for
    /// example the fish's pose in another fish's model frame); <see cref="Frame"/> then carries it onto the fish.
    /// </summary>
    public void SyncModelAt(Vector2 position, float heading)
    {
        Model.SetPose(new FishPose(position, heading, Joint1, Joint2, Joint3));
        ModelStale = position != Position || heading != Heading;
        _frameValid = false;
        _groupsValid = false;
    }

    /// <summary>Marks the pose fields as changed; the model is rebuilt or moved when next needed.</summary>
    public void Invalidate()
    {
        ModelStale = true;
        _frameValid = false;
        _groupsValid = false;
    }

    /// <summary>
    /// Two circles whose union holds the fish at its current pose, without rebuilding the model:
    /// the model's body group and tail group circles carried by <see cref="Frame"/>; after a joint
    /// change, the body group circle carried rigidly with the body and the tail's
    /// <see cref="TailSkeleton"/> circle.
    /// </summary>
    public void Groups(out Disc body, out Disc tail)
    {
        if (!_groupsValid)
        {
            ComputeGroups(out _bodyDisc, out _tailDisc);
            _groupsValid = true;
        }

        body = _bodyDisc;
        tail = _tailDisc;
    }

    private void ComputeGroups(out Disc body, out Disc tail)
    {
        if (!JointsCurrent)
        {
            var (sin, cos) = MathF.SinCos(Heading);
            Vector2 local = _bodyGroupLocal;
            body = new Disc(Position + new Vector2((local.X * cos) - (local.Y * sin), (local.X * sin) + (local.Y * cos)), _bodyGroupRadius);
            tail = TailSkeleton();
            return;
        }

        Circle b = Model.BodyGroup, t = Model.TailGroup;
        if (!ModelStale)
        {
            body = new Disc(b.Center, b.Radius);
            tail = new Disc(t.Center, t.Radius);
            return;
        }

        RigidFrame frame = Frame;
        body = new Disc(frame.ToWorld(b.Center), b.Radius);
        tail = new Disc(frame.ToWorld(t.Center), t.Radius);
    }

    /// <summary>
    /// A circle holding the tail (three segments and the caudal fin) at the current pose and
    /// joints, from its skeleton alone: with S1 = P − (L/2)·u, Eᵢ = Sᵢ − Lᵢ·dᵢ and the caudal
    /// reference point A = E2 − 2·L3·d3, segment 1 lies within h1 = 0.266·L1 of S1E1, segment 2
    /// within h2 = 0.231·L2 of E1E2, and segment 3 with the caudal fin within 50 mm of E2A (the
    /// reference's leaf layout); the circle around the chain's middle that holds those capsules'
    /// end discs holds the tail.
    /// </summary>
    public Disc TailSkeleton()
    {
        FishSize size = Size;
        Vector2 s1 = Position - (0.5f * size.Length * Direction(Heading));
        Vector2 e1 = s1 - (size.Joint1 * Direction(Heading + Joint1));
        Vector2 e2 = e1 - (size.Joint2 * Direction(Heading + Joint2));
        Vector2 a = e2 - (2f * size.Joint3 * Direction(Heading + Joint3));
        float h1 = TailStartHalfWidth1 * size.Joint1, h2 = TailStartHalfWidth2 * size.Joint2;
        Vector2 c = 0.5f * (s1 + a);
        float r = MathF.Max(
            MathF.Max(Vector2.Distance(s1, c) + h1, Vector2.Distance(e1, c) + MathF.Max(h1, h2)),
            MathF.Max(Vector2.Distance(e2, c) + MathF.Max(h2, CaudalReach), Vector2.Distance(a, c) + CaudalReach));
        return new Disc(c, r + 0.01f);
    }

    /// <summary>
    /// A circle enclosing the fish at its current pose without rebuilding the model: the model's
    /// root circle carried by <see cref="Frame"/> (exact, the fish is rigid within a cycle); after a
    /// joint change, the circle around both <see cref="Groups"/> circles.
    /// </summary>
    public Circle Bound()
    {
        Circle root = Model.Root;
        if (!ModelStale)
        {
            return root;
        }

        if (!JointsCurrent)
        {
            Groups(out Disc body, out Disc tail);
            return Enclosing(body, tail);
        }

        return new Circle(Frame.ToWorld(root.Center), root.Radius);
    }
}
