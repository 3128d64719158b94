using URWPGSim2D.Collision.Pool;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// One body of a <see cref="MotionWorld"/>: its shape, its pose now, and its motion within the step.
/// A moving body moves linearly in time from its last committed state (base pose at base time):
/// P = P₀ + v·Δt, θ = θ₀ + ω·Δt, so it can be placed at any time of the step without touching the
/// others. A fish's collision model is rebuilt only when its joints change; otherwise it stays
/// where it was built and <see cref="Frame"/> carries partners into its frame. A polygon's world
/// outline is recomputed, in place, only when a test needs it at a new pose.
/// </summary>
internal sealed class Body
{
    // Reference half-widths of tail segments 1 and 2 at their start (fractions of their lengths),
    // and how far the caudal fin reaches from tail segment 3's axis, mm.
    private const float TailStartHalfWidth1 = 0.266112f;
    private const float TailStartHalfWidth2 = 0.231336f;
    private const float CaudalReach = 50f;

    // Every moving body shares these (never written).
    private static readonly StaticPart NoStatic = new();
    private static readonly PolygonPart NoPolygon = new([], [], 0f);

    private readonly FishBounds? _fish;
    private readonly PolygonPart _polygon = NoPolygon;
    private StaticPart _static = NoStatic;
    private bool _frameValid;
    private bool _groupsValid;
    private bool _outlineValid;

    private Body(BodyKind kind, int id)
    {
        Kind = kind;
        Id = id;
    }

    private Body(int id, PolygonPart polygon)
        : this(BodyKind.Polygon, id)
    {
        _polygon = polygon;
    }

    private Body(int id, FishModel model)
        : this(BodyKind.Fish, id)
    {
        FishPose pose = model.Pose;
        Position = pose.Position;
        Heading = Angle.Wrap(pose.Heading);
        Joint1 = pose.Joint1;
        Joint2 = pose.Joint2;
        Joint3 = pose.Joint3;
        Model = model;

        // The body group (body and pectoral fins) does not depend on the joints: it is rigid with the body.
        Circle group = model.BodyGroup;
        var (sin, cos) = MathF.SinCos(pose.Heading);
        Vector2 offset = group.Center - pose.Position;
        _fish = new FishBounds
        {
            BodyGroupLocal = new Vector2((offset.X * cos) + (offset.Y * sin), (-offset.X * sin) + (offset.Y * cos)),
            BodyGroupRadius = group.Radius,
        };
        FishSize size = model.Size;
        Thickness = MathF.Min(2f * 0.089964f * size.Joint3, size.Width);
        Invalidate();
    }

    /// <summary>The body's number in its motion world.</summary>
    public int Id { get; }

    /// <summary>The id the motion world returned for the body (its number, its motion world's, whether it is static).</summary>
    public BodyId Handle { get; set; }

    /// <summary>What the body is.</summary>
    public BodyKind Kind { get; }

    /// <summary>Whether the body moves (circle, polygon or fish).</summary>
    public bool IsMoving => Kind <= BodyKind.Fish;

    /// <summary>Index among the motion world's movers, or among its static bodies.</summary>
    public int Slot { get; set; }

    /// <summary>A moving circle's radius, mm.</summary>
    public float Radius { get; private init; }

    // What only a static body, the walls, a polygon or a fish has lives in a small object of its own
    // (a shape alone is 256 bytes), so that a ball's state stays small: every pass over the movers
    // and every test reads it.

    /// <summary>A static body's shape (<c>default</c> for any other body).</summary>
    public ref readonly Shape Shape => ref _static.Shape;

    /// <summary>Whether the body is a static circle (its bounds test is <see cref="StaticDisc"/> rather than <see cref="Bounds"/>).</summary>
    public bool RoundStatic => _static.Round;

    /// <summary>A static body's bounding circle (kept so that bounds tests need not read <see cref="Shape"/>).</summary>
    public Disc StaticDisc => _static.Disc;

    /// <summary>A static body's bounds, or the walls' pool bounds.</summary>
    public Aabb Bounds => _static.Bounds;

    /// <summary>The pool whose walls this body is.</summary>
    public Field? Field => _static.Field;

    /// <summary>A moving polygon's vertices about its origin.</summary>
    public Vector2[] LocalVertices => _polygon.LocalVertices;

    /// <summary>Outward edge normals of <see cref="LocalVertices"/>.</summary>
    public Vector2[] LocalNormals => _polygon.LocalNormals;

    /// <summary>A moving polygon's outline at its current pose (valid after <see cref="Outline"/>).</summary>
    public Vector2[] WorldVertices => _polygon.WorldVertices;

    /// <summary>Outward edge normals of <see cref="WorldVertices"/>.</summary>
    public Vector2[] WorldNormals => _polygon.WorldNormals;

    /// <summary>Farthest point of a polygon from its origin, mm.</summary>
    public float Reach => _polygon.Reach;

    /// <summary>A fish's collision model (at the pose it was last built for).</summary>
    public FishModel? Model { get; }

    /// <summary>Thinnest width, mm (a ball's diameter, the end of a fish's tail, a polygon's narrowest width; walls: infinite).</summary>
    public float Thickness { get; private set; }

    /// <summary>Position now, mm.</summary>
    public Vector2 Position;

    /// <summary>Heading now, rad, wrapped to [−π, π).</summary>
    public float Heading;

    /// <summary>A fish's joint angles now, rad (fixed within a step unless they turn over it: <see cref="AimJoints"/>).</summary>
    public float Joint1, Joint2, Joint3;

    /// <summary>The velocity the body moves with, mm/s: its own plus its drift (<see cref="SetMotion"/>).</summary>
    public Vector2 Velocity;

    /// <summary>The angular velocity the body turns with, rad/s (positive turns from +X toward +Z): its own plus its drift.</summary>
    public float AngularVelocity;

    /// <summary>The body's own velocity, mm/s (what a contact response changes).</summary>
    public Vector2 OwnVelocity;

    /// <summary>The body's own angular velocity, rad/s.</summary>
    public float OwnAngularVelocity;

    /// <summary>A drift added to the motion only (noise, say), mm/s.</summary>
    public Vector2 Drift;

    /// <summary>A turning drift added to the motion only, rad/s.</summary>
    public float AngularDrift;

    /// <summary>Pose at the last committed time.</summary>
    public Vector2 BasePosition;

    /// <summary>Heading at the last committed time.</summary>
    public float BaseHeading;

    /// <summary>The last committed time (fraction of the step, 0 … 1).</summary>
    public double BaseTime;

    /// <summary>Pose at the end of the previous step (a rejected move goes back there).</summary>
    public Vector2 StartPosition;

    /// <summary>Heading at the end of the previous step.</summary>
    public float StartHeading;

    /// <summary>A fish's joints at the end of the previous step.</summary>
    public float StartJoint1, StartJoint2, StartJoint3;

    /// <summary>
    /// Where the last step began from (the start pose and joints as they were then): a move rejected
    /// by the caller's response goes back there, also while <c>Settle</c> runs after the step.
    /// </summary>
    public Vector2 StepStartPosition;

    /// <summary>Heading the last step began from.</summary>
    public float StepStartHeading;

    /// <summary>A fish's joints the last step began from.</summary>
    public float StepStartJoint1, StepStartJoint2, StepStartJoint3;

    /// <summary>Changes whenever the body's shape changes (a fish's joints), so that remembered tests are not reused.</summary>
    public int ShapeStamp;

    /// <summary>Contact events of the body in the current step.</summary>
    public int Events;

    /// <summary>Step time of the body's last contact event (−1: none yet in this step).</summary>
    public double LastEventTime = -1.0;

    /// <summary>Events in a row at the time of the one before (the body is pushed back and forth without getting anywhere).</summary>
    public int EventsInPlace;

    /// <summary>Whether the body takes part in contacts (false: it is never paired, not even with the walls).</summary>
    public bool Collides = true;

    /// <summary>The caller's tag (see <see cref="MotionWorld.TagOf"/>).</summary>
    public int Tag;

    /// <summary>Whether the body's move was rejected since the current or last step began.</summary>
    public bool Rejected;

    /// <summary>Deep position corrections by the handler's separation this step (<see cref="IContactHandler.OnSeparate"/>).</summary>
    public int Corrections;

    /// <summary>A moving circle.</summary>
    public static Body Circle(int id, float radius, Vector2 position) =>
        new(BodyKind.Circle, id) { Radius = radius, Position = position, Thickness = 2f * radius };

    /// <summary>A moving polygon given about its origin, placed at a pose.</summary>
    public static Body Polygon(int id, in ConvexPolygon local, Vector2 position, float heading)
    {
        var v = local.Vertices.ToArray();
        var n = local.Normals.ToArray();
        float reach = 0f;
        foreach (Vector2 p in v)
        {
            reach = MathF.Max(reach, p.Length());
        }

        return new Body(id, new PolygonPart(v, n, reach))
        {
            Position = position,
            Heading = Angle.Wrap(heading),
            Thickness = Width(v, n),
        };
    }

    /// <summary>A moving fish.</summary>
    public static Body Fish(int id, FishSize size, in FishPose pose) => new(id, new FishModel(size, pose));

    /// <summary>A moving fish around an existing model (at the model's pose).</summary>
    public static Body Fish(int id, FishModel model) => new(id, model);

    /// <summary>A static shape.</summary>
    public static Body Static(int id, in Shape shape)
    {
        var body = new Body(BodyKind.Static, id);
        body.Reshape(shape);
        return body;
    }

    /// <summary>Gives a static body another shape (its shape stamp changes, so no remembered test is reused).</summary>
    public void Reshape(in Shape shape)
    {
        Circle c = shape.BoundingCircle;
        Aabb bounds = shape.Kind switch
        {
            ShapeKind.Aabb => shape.AsAabb(),
            ShapeKind.Circle => new Aabb(c.Center - new Vector2(c.Radius), c.Center + new Vector2(c.Radius)),
            ShapeKind.Segment => new Aabb(Vector2.Min(shape.AsSegment().A, shape.AsSegment().B), Vector2.Max(shape.AsSegment().A, shape.AsSegment().B)),
            ShapeKind.KDop8 => BoxOf(shape.AsKDop8().Vertices),
            _ => BoxOf(shape.AsPolygon().Vertices),
        };
        Thickness = shape.Kind switch
        {
            ShapeKind.Circle => 2f * c.Radius,
            ShapeKind.Aabb => MathF.Min(bounds.Max.X - bounds.Min.X, bounds.Max.Y - bounds.Min.Y),
            ShapeKind.Segment => 0f,
            ShapeKind.KDop8 => KDopWidth(shape.AsKDop8()),
            _ => Width(shape.AsPolygon().Vertices, shape.AsPolygon().Normals),
        };
        if (ReferenceEquals(_static, NoStatic))
        {
            _static = new StaticPart();
        }

        _static.Shape = shape;
        _static.Bounds = bounds;
        _static.Round = shape.Kind == ShapeKind.Circle;
        _static.Disc = new Disc(c.Center, c.Radius);
        Position = c.Center;
        BasePosition = c.Center;
        ShapeStamp++;
    }

    /// <summary>The walls of a pool.</summary>
    public static Body Walls(int id, Field field) =>
        new(BodyKind.Walls, id) { _static = new StaticPart { Field = field, Bounds = field.Bounds }, Thickness = float.PositiveInfinity };

    /// <summary>The motion from the body's own velocities and its drifts (a circle does not turn).</summary>
    public void SetMotion()
    {
        Velocity = OwnVelocity + Drift;
        AngularVelocity = Kind == BodyKind.Circle ? 0f : OwnAngularVelocity + AngularDrift;
    }

    /// <summary>
    /// The body starts a step where it is: its motion measured from time 0, its start pose kept as
    /// the step's (<see cref="KeepStepStart"/>), and the last step's counts of events, corrections
    /// and rejection cleared.
    /// </summary>
    public void StartStep()
    {
        if (_fish is { TurnPending: true } turn)
        {
            StartJointTurn(turn);
        }

        Rebase(0.0);
        KeepStepStart();
        Events = 0;
        EventsInPlace = 0;
        LastEventTime = -1.0;
        Rejected = false;
        Corrections = 0;
    }

    /// <summary>A fish's joints turn to these angles over the next step (from its joints when the step starts).</summary>
    public void AimJoints(float joint1, float joint2, float joint3)
    {
        FishBounds turn = _fish!;
        turn.TurnTo = new Vector3(joint1, joint2, joint3);
        turn.TurnPending = true;
    }

    /// <summary>A fish's joints hold their angles from now on: a turn set for the next step, or running in this one, stops.</summary>
    public void HoldJoints()
    {
        if (_fish is { } turn)
        {
            turn.TurnPending = false;
            turn.TurnActive = false;
        }
    }

    /// <summary>Most a point of the body moves over a whole step by its joints' turning, mm (0 while they hold).</summary>
    public float JointSwing => _fish is { TurnActive: true } turn ? turn.Swing : 0f;

    /// <summary>
    /// The most a point of a fish of <paramref name="size"/> moves while its joints turn by the
    /// given angles, mm: each joint angle is the direction of its own segment in the body frame, so
    /// turning joint k turns its segment about the segment's start (a point of segment 1 lies
    /// within L1 + h1 of it, of segment 2 within L2 + h2, of segment 3 and the caudal fin within
    /// 2·L3 + 50 mm) and carries the later segments along by at most as much; the turns add up.
    /// </summary>
    public static float Swing(FishSize size, Vector3 turned)
    {
        Vector3 t = Vector3.Abs(turned);
        return (t.X * size.Joint1 * (1f + TailStartHalfWidth1))
            + (t.Y * size.Joint2 * (1f + TailStartHalfWidth2))
            + (t.Z * ((2f * size.Joint3) + CaudalReach));
    }

    /// <summary>The start pose becomes where this step begins from (see <see cref="StepStartPosition"/>).</summary>
    public void KeepStepStart()
    {
        StepStartPosition = StartPosition;
        StepStartHeading = StartHeading;
        (StepStartJoint1, StepStartJoint2, StepStartJoint3) = (StartJoint1, StartJoint2, StartJoint3);
    }

    /// <summary>Stops the body: own velocities and drifts zero.</summary>
    public void Stop()
    {
        (OwnVelocity, Drift, Velocity) = (default, default, default);
        (OwnAngularVelocity, AngularDrift, AngularVelocity) = (0f, 0f, 0f);
    }

    /// <summary>Places the body at step time <paramref name="time"/> along its motion (a step lasting <paramref name="seconds"/>).</summary>
    public void MoveTo(double time, float seconds)
    {
        if (_fish is { TurnActive: true } turn)
        {
            TurnJointsTo(turn, time);
        }

        float span = (float)((time - BaseTime) * seconds);
        Vector2 position = BasePosition + (Velocity * span);
        float heading = Kind == BodyKind.Circle ? Heading : Angle.Wrap(BaseHeading + (AngularVelocity * span));
        if (position == Position && heading == Heading)
        {
            return;
        }

        Position = position;
        Heading = heading;
        Invalidate();
    }

    /// <summary>The step ends, or the body's move is rejected: a turn running in the step stops, the joints hold where they are (a turn set for the next step stays set).</summary>
    public void EndJointTurn()
    {
        if (_fish is { } turn)
        {
            turn.TurnActive = false;
        }
    }

    // The joints of a turning fish at a step time: linear in time from the step's start, exactly
    // the targets at its end. A change of angles is a change of shape (no remembered test reused).
    private void TurnJointsTo(FishBounds turn, double time)
    {
        Vector3 joints = time >= 1.0 ? turn.TurnTo : turn.TurnFrom + ((turn.TurnTo - turn.TurnFrom) * (float)Math.Max(time, 0.0));
        if (joints.X == Joint1 && joints.Y == Joint2 && joints.Z == Joint3)
        {
            return;
        }

        (Joint1, Joint2, Joint3) = (joints.X, joints.Y, joints.Z);
        ShapeStamp++;
        Invalidate();
    }

    // A pending turn starts with the step, from the joints the fish has now.
    private void StartJointTurn(FishBounds turn)
    {
        turn.TurnPending = false;
        turn.TurnFrom = new Vector3(Joint1, Joint2, Joint3);
        turn.TurnActive = turn.TurnTo != turn.TurnFrom;
        turn.Swing = turn.TurnActive ? Swing(Model!.Size, turn.TurnTo - turn.TurnFrom) : 0f;
    }

    /// <summary>Commits the current pose as the body's state at <paramref name="time"/>.</summary>
    public void Rebase(double time)
    {
        BasePosition = Position;
        BaseHeading = Heading;
        BaseTime = time;
    }

    /// <summary>Marks the pose as changed: derived outlines, frames and bounds are recomputed when next needed.</summary>
    public void Invalidate()
    {
        ModelStale = Kind == BodyKind.Fish;
        _frameValid = false;
        _groupsValid = false;
        _outlineValid = false;
    }

    /// <summary>A polygon's outline at its current pose (vertices and normals in <see cref="WorldVertices"/>, <see cref="WorldNormals"/>).</summary>
    public void Outline()
    {
        if (_outlineValid)
        {
            return;
        }

        var (sin, cos) = MathF.SinCos(Heading);
        for (int i = 0; i < LocalVertices.Length; i++)
        {
            Vector2 v = LocalVertices[i], n = LocalNormals[i];
            WorldVertices[i] = Position + new Vector2((v.X * cos) - (v.Y * sin), (v.X * sin) + (v.Y * cos));
            WorldNormals[i] = new Vector2((n.X * cos) - (n.Y * sin), (n.X * sin) + (n.Y * cos));
        }

        _outlineValid = true;
    }

    /// <summary>Whether <see cref="Model"/> lags behind the pose (it is rebuilt only when a test needs it).</summary>
    public bool ModelStale { get; private set; }

    /// <summary>The fish's model exactly at the current pose (rebuilt first if it lags behind).</summary>
    public FishModel PosedModel
    {
        get
        {
            if (ModelStale && !(JointsCurrent && Frame.IsIdentity))
            {
                SyncModelAt(Position, Heading);
            }

            return Model!;
        }
    }

    /// <summary>The fish's model with the current joints, rebuilt only when they changed; related to the fish by <see cref="Frame"/>.</summary>
    public FishModel RigidModel
    {
        get
        {
            if (!JointsCurrent)
            {
                SyncModelAt(Position, Heading);
            }

            return Model!;
        }
    }

    /// <summary>The rigid motion from the model's pose to the fish's current position and heading.</summary>
    public RigidFrame Frame
    {
        get
        {
            if (!_frameValid)
            {
                // Most changes of pose move the fish without turning it (or its model): the turn's
                // sine and cosine are kept from the last frame when the turn is the same.
                FishPose posed = Model!.Pose;
                FishBounds fish = _fish!;
                fish.Frame = fish.Frame.Turn == Heading - posed.Heading
                    ? fish.Frame.Moved(posed.Position, Position)
                    : new RigidFrame(posed.Position, posed.Heading, Position, Heading);
                _frameValid = true;
            }

            return _fish!.Frame;
        }
    }

    /// <summary>Whether the model was built with the current joint angles.</summary>
    public bool JointsCurrent
    {
        get
        {
            FishPose posed = Model!.Pose;
            return posed.Joint1 == Joint1 && posed.Joint2 == Joint2 && posed.Joint3 == Joint3;
        }
    }

    /// <summary>Rebuilds the fish's model with the current joints at a given position and heading (for example in another fish's model frame).</summary>
    public void SyncModelAt(Vector2 position, float heading)
    {

        Model!.SetPose(new FishPose(position, heading, Joint1, Joint2, Joint3));
        ModelStale = position != Position || heading != Heading;
        _frameValid = false;
        _groupsValid = false;
    }

    /// <summary>
    /// Two circles whose union holds the body now, without rebuilding anything: a fish's body group
    /// and tail group circles (carried by <see cref="Frame"/>; after a joint change, the body group
    /// carried with the body and the tail's skeleton circle); any other body's bounding circle twice.
    /// </summary>
    public void Groups(out Disc first, out Disc second)
    {
        if (Kind != BodyKind.Fish)
        {
            first = Kind == BodyKind.Circle ? new Disc(Position, Radius) : Kind == BodyKind.Polygon ? new Disc(Position, Reach) : new Disc(Position, StaticDisc.Radius);
            second = first;
            return;
        }

        if (!_groupsValid)
        {
            ComputeGroups(out _fish!.BodyDisc, out _fish.TailDisc);
            _groupsValid = true;
        }

        first = _fish!.BodyDisc;
        second = _fish.TailDisc;
    }

    /// <summary>A circle enclosing the moving body now.</summary>
    public Disc Bound()
    {
        switch (Kind)
        {
            case BodyKind.Circle:
                return new Disc(Position, Radius);
            case BodyKind.Polygon:
                return new Disc(Position, Reach);
        }

        Circle root = Model!.Root;
        if (!ModelStale)
        {
            return new Disc(root.Center, root.Radius);
        }

        if (!JointsCurrent)
        {
            Groups(out Disc body, out Disc tail);
            return Enclosing(body, tail);
        }

        return new Disc(Frame.ToWorld(root.Center), root.Radius);
    }

    /// <summary>
    /// A circle holding the tail (three segments and the caudal fin) at the current pose and
    /// joints from its skeleton alone: with S1 = P − (L/2)·u, Eᵢ = Sᵢ − Lᵢ·dᵢ and the caudal
    /// reference point A = E2 − 2·L3·d3, segment 1 lies within h1 = 0.266·L1 of S1E1, segment 2
    /// within h2 = 0.231·L2 of E1E2, and segment 3 with the caudal fin within 50 mm of E2A.
    /// </summary>
    public Disc TailSkeleton()
    {
        var (sin, cos) = MathF.SinCos(Heading);
        return TailSkeleton(sin, cos);
    }

    // The tail's circle in the body frame depends on the joints alone: computed once per joint
    // angles, then carried with the body (its 0.01 mm slack covers the rounding of either way).
    private Disc TailSkeleton(float sin, float cos)
    {
        FishBounds fish = _fish!;
        if (fish.TailJoints != new Vector3(Joint1, Joint2, Joint3) || fish.TailRadius == 0f)
        {
            FishSize size = Model!.Size;
            Vector2 s1 = new(-0.5f * size.Length, 0f);
            Vector2 e1 = s1 - (size.Joint1 * Direction(Joint1));
            Vector2 e2 = e1 - (size.Joint2 * Direction(Joint2));
            Vector2 a = e2 - (2f * size.Joint3 * Direction(Joint3));
            float h1 = TailStartHalfWidth1 * size.Joint1, h2 = TailStartHalfWidth2 * size.Joint2;
            Vector2 c = 0.5f * (s1 + a);
            float r = MathF.Max(
                MathF.Max(Vector2.Distance(s1, c) + h1, Vector2.Distance(e1, c) + MathF.Max(h1, h2)),
                MathF.Max(Vector2.Distance(e2, c) + MathF.Max(h2, CaudalReach), Vector2.Distance(a, c) + CaudalReach));
            fish.TailLocal = c;
            fish.TailRadius = r + 0.01f;
            fish.TailJoints = new Vector3(Joint1, Joint2, Joint3);
        }

        Vector2 l = fish.TailLocal;
        return new Disc(Position + new Vector2((l.X * cos) - (l.Y * sin), (l.X * sin) + (l.Y * cos)), fish.TailRadius);
    }

    private void ComputeGroups(out Disc body, out Disc tail)
    {
        if (!JointsCurrent)
        {
            var (sin, cos) = MathF.SinCos(Heading);
            FishBounds fish = _fish!;
            Vector2 local = fish.BodyGroupLocal;
            body = new Disc(Position + new Vector2((local.X * cos) - (local.Y * sin), (local.X * sin) + (local.Y * cos)), fish.BodyGroupRadius);
            tail = TailSkeleton(sin, cos);
            return;
        }

        Circle b = Model!.BodyGroup, t = Model.TailGroup;
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

    private static Vector2 Direction(float angle)
    {
        var (sin, cos) = MathF.SinCos(angle);
        return new Vector2(cos, sin);
    }

    // The smallest circle holding both circles.
    private static Disc Enclosing(in Disc a, in Disc b)
    {
        float d = Vector2.Distance(a.Center, b.Center);
        if (d + b.Radius <= a.Radius)
        {
            return a;
        }

        if (d + a.Radius <= b.Radius)
        {
            return b;
        }

        float r = 0.5f * (d + a.Radius + b.Radius);
        Vector2 c = a.Center + ((b.Center - a.Center) * ((r - a.Radius) / d));
        return new Disc(c, r + 0.01f);
    }

    private static Aabb BoxOf(ReadOnlySpan<Vector2> points)
    {
        Vector2 lo = points[0], hi = points[0];
        foreach (Vector2 p in points)
        {
            lo = Vector2.Min(lo, p);
            hi = Vector2.Max(hi, p);
        }

        return new Aabb(lo, hi);
    }

    // The narrowest width of a convex outline: the least extent along its edge normals.
    private static float Width(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals)
    {
        float width = float.PositiveInfinity;
        foreach (Vector2 n in normals)
        {
            float lo = float.PositiveInfinity, hi = float.NegativeInfinity;
            foreach (Vector2 v in vertices)
            {
                float p = Vector2.Dot(v, n);
                lo = MathF.Min(lo, p);
                hi = MathF.Max(hi, p);
            }

            width = MathF.Min(width, hi - lo);
        }

        return width;
    }

    private static float KDopWidth(in KDop8 kdop)
    {
        float width = float.PositiveInfinity;
        for (int axis = 0; axis < 4; axis++)
        {
            width = MathF.Min(width, (kdop.GetMax(axis) - kdop.GetMin(axis)) / KDop8.Axis(axis).Length());
        }

        return width;
    }

    // A fish's bounds that follow from its pose, kept apart from the body so that a ball's or a
    // polygon's state stays small: what the body group is in the body frame, and the last frame,
    // group circles and tail circle computed (valid while the body's flags say so; the last frame's
    // turn is reused by the next frame of the same turn, the first frame a built one of no turn); and its joints'
    // turn over a step: set between steps (pending), running in the step (active) from the angles
    // it started with to the targets, with the most a point moves by it.
    private sealed class FishBounds
    {
        public Vector3 TurnFrom;
        public Vector3 TurnTo;
        public float Swing;
        public bool TurnPending;
        public bool TurnActive;
        public Vector2 BodyGroupLocal;
        public float BodyGroupRadius;
        public RigidFrame Frame = new(Vector2.Zero, 0f, Vector2.Zero, 0f);
        public Disc BodyDisc;
        public Disc TailDisc;
        public Vector3 TailJoints;
        public Vector2 TailLocal;
        public float TailRadius;
    }

    // A static body's shape, bounding circle and bounds (the walls: their pool and its bounds).
    private sealed class StaticPart
    {
        public Shape Shape;
        public Disc Disc;
        public Aabb Bounds;
        public bool Round;
        public Field? Field;
    }

    // A moving polygon's outline about its origin, its outline at the current pose, and its reach.
    private sealed class PolygonPart(Vector2[] local, Vector2[] normals, float reach)
    {
        public readonly Vector2[] LocalVertices = local;
        public readonly Vector2[] LocalNormals = normals;
        public readonly Vector2[] WorldVertices = new Vector2[local.Length];
        public readonly Vector2[] WorldNormals = new Vector2[local.Length];
        public readonly float Reach = reach;
    }
}
