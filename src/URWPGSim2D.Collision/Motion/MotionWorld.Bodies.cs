using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.Runtime.CompilerServices;
using URWPGSim2D.Collision.Pool;

namespace URWPGSim2D.Collision.Motion;

/// <content>
/// The bodies, which the world owns: adding them, reading and changing their state, testing a pair
/// now. During a step the world also keeps the bodies a response has changed since they were last
/// committed (<see cref="ChangedBodies"/>), in the order they were first changed.
/// </content>
public sealed partial class MotionWorld
{
    private readonly List<Body> _bodies = [];
    private readonly int _world = BodyId.NextWorld();
    private readonly LeafContacts _leaves = new();
    private BodySet _changed = new(0);
    private int _generation = 1;
    private bool _loaded;
    private bool _stepping;

    /// <summary>Number of bodies (their ids' <see cref="BodyId.Index"/> are 0 … BodyCount − 1, in the order they were added).</summary>
    public int BodyCount => _bodies.Count;

    /// <summary>Adds a moving circle (a ball).</summary>
    /// <param name="radius">Radius, mm (positive, finite).</param>
    /// <param name="position">Centre, mm.</param>
    /// <returns>The body's id.</returns>
    /// <exception cref="ArgumentException">The radius or position is invalid, or a step is running.</exception>
    public BodyId AddCircle(float radius, Vector2 position)
    {
        _ = new Circle(position, radius);
        return Add(Body.Circle(_bodies.Count, radius, position));
    }

    /// <summary>Adds a moving convex polygon; it turns about its own origin.</summary>
    /// <param name="shape">The outline about the body's origin, mm.</param>
    /// <param name="position">Where the origin is, mm.</param>
    /// <param name="heading">How far the outline is turned, rad (positive from +X toward +Z).</param>
    /// <returns>The body's id.</returns>
    /// <exception cref="ArgumentException">The polygon is default, the pose is not finite, or a step is running.</exception>
    public BodyId AddPolygon(in ConvexPolygon shape, Vector2 position, float heading)
    {
        if (shape.Vertices.Length == 0)
        {
            throw new ArgumentException("polygon is default(ConvexPolygon) and has no vertices", nameof(shape));
        }

        Guard.Finite(position, nameof(position));
        Finite(heading, nameof(heading));
        return Add(Body.Polygon(_bodies.Count, shape, position, heading));
    }

    /// <summary>Adds a moving fish; it turns about its body centre and its joints keep their angles within a step unless set to turn over it (<see cref="SetJointTargets"/>).</summary>
    /// <param name="size">The fish's dimensions.</param>
    /// <param name="pose">Its position, heading and joint angles.</param>
    /// <returns>The body's id.</returns>
    /// <exception cref="ArgumentException">The size is default, or a step is running.</exception>
    public BodyId AddFish(FishSize size, in FishPose pose) => Add(Body.Fish(_bodies.Count, size, pose));

    /// <summary>Adds a static body: a circle, box, 8-DOP, convex polygon or segment (each converts to <see cref="Shape"/>).</summary>
    /// <param name="shape">The shape, mm.</param>
    /// <returns>The body's id.</returns>
    /// <exception cref="ArgumentException">The shape is default, or a step is running.</exception>
    public BodyId AddStatic(in Shape shape)
    {
        if (shape.Kind == ShapeKind.Polygon && shape.AsPolygon().Vertices.Length == 0)
        {
            throw new ArgumentException("polygon is default(ConvexPolygon) and has no vertices", nameof(shape));
        }

        return Add(Body.Static(_bodies.Count, shape));
    }

    /// <summary>Adds the pool's four walls: every moving body must stay inside <paramref name="field"/>'s bounds (its goal blocks are added separately, as boxes).</summary>
    /// <param name="field">The pool.</param>
    /// <returns>The walls' id.</returns>
    /// <exception cref="ArgumentException">The motion world has walls already, or a step is running.</exception>
    public BodyId AddWalls(Field field)
    {
        ArgumentNullException.ThrowIfNull(field);
        foreach (Body b in _bodies)
        {
            if (b.Kind == BodyKind.Walls)
            {
                throw new ArgumentException($"the motion world has walls already ({b.Handle})", nameof(field));
            }
        }

        return Add(Body.Walls(_bodies.Count, field));
    }

    /// <summary>
    /// Removes every body: the motion world is empty again, its settings (<see cref="Wedging"/>,
    /// <see cref="Threads"/>, <see cref="MinimumMoversForThreads"/>, <see cref="HeldSubSteps"/>,
    /// <see cref="PressingContacts"/>) kept, and the next body added is number 0. The ids of the removed
    /// bodies are stale: every method refuses them with an <see cref="ArgumentException"/> that
    /// says so, even where a new body has the same number.
    /// </summary>
    /// <exception cref="InvalidOperationException">A step or <see cref="Settle"/> is running.</exception>
    public void Clear()
    {
        if (_stepping)
        {
            throw new InvalidOperationException("the motion world cannot be cleared while a step or Settle runs");
        }

        _bodies.Clear();
        _contacts.Clear();
        _generation++;
        _loaded = false;
    }

    /// <summary>
    /// Forgets every touch (<see cref="IsTouching"/>), as <see cref="Clear"/> does, without ending
    /// it (no <see cref="IContactHandler.OnTouchEnded"/>): the next step treats every pair as not
    /// touching, so no pair is held at its start (<see cref="HeldSubSteps"/>) and each pair's next
    /// contact is a first contact. For a game put back to its start in place, which should then play what a new
    /// motion world of the same bodies plays.
    /// </summary>
    /// <exception cref="InvalidOperationException">A step or <see cref="Settle"/> is running.</exception>
    public void ForgetTouches()
    {
        if (_stepping)
        {
            throw new InvalidOperationException("touches cannot be forgotten while a step or Settle runs");
        }

        _contacts.Clear();
    }

    /// <summary>What a body is.</summary>
    /// <param name="body">The body's id.</param>
    /// <returns>Its kind.</returns>
    public BodyKind KindOf(BodyId body) => Get(body).Kind;

    /// <summary>A body's position now, mm (a static body: its bounding circle's centre).</summary>
    /// <param name="body">The body's id.</param>
    /// <returns>The position.</returns>
    public Vector2 PositionOf(BodyId body) => Get(body).Position;

    /// <summary>A body's heading now, rad.</summary>
    /// <param name="body">The body's id.</param>
    /// <returns>The heading, wrapped to [−π, π).</returns>
    public float HeadingOf(BodyId body) => Get(body).Heading;

    /// <summary>A moving body's own velocity, mm/s (it moves with this plus its <see cref="DriftOf"/>).</summary>
    /// <param name="body">The body's id.</param>
    /// <returns>The velocity.</returns>
    public Vector2 VelocityOf(BodyId body) => Get(body).OwnVelocity;

    /// <summary>A moving body's own angular velocity, rad/s (it turns with this plus its <see cref="AngularDriftOf"/>).</summary>
    /// <param name="body">The body's id.</param>
    /// <returns>The angular velocity.</returns>
    public float AngularVelocityOf(BodyId body) => Get(body).OwnAngularVelocity;

    /// <summary>A moving body's drift, mm/s: added to its motion, not to its velocity (see <see cref="SetDrift"/>).</summary>
    /// <param name="body">The body's id.</param>
    /// <returns>The drift.</returns>
    public Vector2 DriftOf(BodyId body) => Get(body).Drift;

    /// <summary>A moving body's turning drift, rad/s (see <see cref="SetDrift"/>).</summary>
    /// <param name="body">The body's id.</param>
    /// <returns>The turning drift.</returns>
    public float AngularDriftOf(BodyId body) => Get(body).AngularDrift;

    /// <summary>A fish's collision model at its current pose (read only: the motion world owns it).</summary>
    /// <param name="fish">The fish's id.</param>
    /// <returns>The model.</returns>
    /// <exception cref="ArgumentException">The body is not a fish.</exception>
    public FishModel FishModelOf(BodyId fish) => Moving(fish, BodyKind.Fish, nameof(fish)).PosedModel;

    /// <summary>A fish's pose now: position, heading and joint angles, as the motion world holds them.</summary>
    /// <param name="fish">The fish's id.</param>
    /// <returns>The pose a <see cref="FishModel"/> of the fish's size is laid out at to show the fish now.</returns>
    /// <exception cref="ArgumentException">The body is not a fish.</exception>
    public FishPose FishPoseOf(BodyId fish)
    {
        Body b = Moving(fish, BodyKind.Fish, nameof(fish));
        return new FishPose(b.Position, b.Heading, b.Joint1, b.Joint2, b.Joint3);
    }

    /// <summary>
    /// Places a moving body. Between steps this is a jump (the new pose is also where a rejected
    /// move goes back to); during a handler call it is the body's pose at <see cref="Time"/>, from
    /// which it moves on.
    /// </summary>
    /// <param name="body">The body's id.</param>
    /// <param name="position">Position, mm.</param>
    /// <param name="heading">Heading, rad (ignored for a circle).</param>
    /// <exception cref="ArgumentException">The body does not move, or the pose is not finite.</exception>
    public void SetPose(BodyId body, Vector2 position, float heading)
    {
        Body b = Moving(body, null, nameof(body));
        Guard.Finite(position, nameof(position));
        Finite(heading, nameof(heading));
        Touch(b);
        b.Position = position;
        b.Heading = b.Kind == BodyKind.Circle ? 0f : Angle.Wrap(heading);
        b.Invalidate();
        Commit(b);
        QueryMoved(b);
        if (!_stepping)
        {
            b.StartPosition = b.Position;
            b.StartHeading = b.Heading;
        }
    }

    /// <summary>
    /// Sets the angles a fish's joints turn to over the next step: through it they turn linearly
    /// in time from their angles at its start and reach these at its end. The tail is swept like
    /// any motion (its sampling and swept bounds cover the turn), so a contact of the turning tail
    /// is found at its time of first contact instead of as an overlap at the start of the step, as
    /// after <see cref="SetJoints"/>. Until the step the fish keeps its joints (<see cref="FishPoseOf"/>
    /// shows them); a later call replaces the targets. A turn lasts one step; <see cref="SetJoints"/>
    /// stops it, and so does a move rejected in the step (the fish goes back to where it began the
    /// step, see <see cref="RejectMove"/>); a move that <see cref="Settle"/> rejects before the step
    /// leaves the targets set.
    /// </summary>
    /// <param name="fish">The fish's id.</param>
    /// <param name="joint1">Joint 1 at the end of the next step, rad.</param>
    /// <param name="joint2">Joint 2 at the end of the next step, rad.</param>
    /// <param name="joint3">Joint 3 at the end of the next step, rad.</param>
    /// <exception cref="ArgumentException">The body is not a fish, an angle is not finite, or a step is running.</exception>
    public void SetJointTargets(BodyId fish, float joint1, float joint2, float joint3)
    {
        Body b = Moving(fish, BodyKind.Fish, nameof(fish));
        Finite(joint1, nameof(joint1));
        Finite(joint2, nameof(joint2));
        Finite(joint3, nameof(joint3));
        if (_stepping)
        {
            throw new ArgumentException($"{fish}: joint targets can be set only between steps", nameof(fish));
        }

        b.AimJoints(joint1, joint2, joint3);
    }

    /// <summary>Sets a fish's joint angles now (they hold for the rest of the step; a turn set by <see cref="SetJointTargets"/> stops).</summary>
    /// <param name="fish">The fish's id.</param>
    /// <param name="joint1">Joint 1, rad.</param>
    /// <param name="joint2">Joint 2, rad.</param>
    /// <param name="joint3">Joint 3, rad.</param>
    /// <exception cref="ArgumentException">The body is not a fish, or an angle is not finite.</exception>
    public void SetJoints(BodyId fish, float joint1, float joint2, float joint3)
    {
        Body b = Moving(fish, BodyKind.Fish, nameof(fish));
        Finite(joint1, nameof(joint1));
        Finite(joint2, nameof(joint2));
        Finite(joint3, nameof(joint3));
        Touch(b);
        b.HoldJoints();
        b.Joint1 = joint1;
        b.Joint2 = joint2;
        b.Joint3 = joint3;
        b.ShapeStamp++;
        b.Invalidate();
        Commit(b);
        QueryMoved(b);
    }

    /// <summary>Sets a moving body's own velocity; it moves with this plus its drift (<see cref="SetDrift"/>). For the rest of the step when called from a handler.</summary>
    /// <param name="body">The body's id.</param>
    /// <param name="velocity">Velocity, mm/s.</param>
    /// <param name="angularVelocity">Angular velocity, rad/s (ignored for a circle).</param>
    /// <exception cref="ArgumentException">The body does not move, or a value is not finite.</exception>
    public void SetVelocity(BodyId body, Vector2 velocity, float angularVelocity = 0f)
    {
        Body b = Moving(body, null, nameof(body));
        Guard.Finite(velocity, nameof(velocity));
        Finite(angularVelocity, nameof(angularVelocity));
        Touch(b);
        b.OwnVelocity = velocity;
        b.OwnAngularVelocity = b.Kind == BodyKind.Circle ? 0f : angularVelocity;
        b.SetMotion();
        Commit(b);
    }

    /// <summary>
    /// Sets a moving body's drift: a velocity added to its motion but not to its own velocity (a
    /// simulator's noise, say: <see cref="VelocityOf"/> and a contact response see the body's own
    /// velocity, while the body moves with the sum). Zero for every body until set; a rejected
    /// move clears it. For the rest of the step when called from a handler.
    /// </summary>
    /// <param name="body">The body's id.</param>
    /// <param name="drift">Drift, mm/s.</param>
    /// <param name="angularDrift">Turning drift, rad/s (ignored for a circle).</param>
    /// <exception cref="ArgumentException">The body does not move, or a value is not finite.</exception>
    public void SetDrift(BodyId body, Vector2 drift, float angularDrift = 0f)
    {
        Body b = Moving(body, null, nameof(body));
        Guard.Finite(drift, nameof(drift));
        Finite(angularDrift, nameof(angularDrift));
        Touch(b);
        b.Drift = drift;
        b.AngularDrift = b.Kind == BodyKind.Circle ? 0f : angularDrift;
        b.SetMotion();
        Commit(b);
    }

    /// <summary>
    /// Takes a moving body out of contact handling, or back in. A body that does not collide is never
    /// paired with anything (bodies, static bodies or walls) and may even lie outside the pool; it
    /// still moves with its velocity. Used e.g. to park a body that is out of play.
    /// </summary>
    /// <param name="body">The body's id.</param>
    /// <param name="collides">True (the default for every body) to take part in contacts.</param>
    /// <exception cref="ArgumentException">The body does not move.</exception>
    public void SetCollides(BodyId body, bool collides)
    {
        Body b = Moving(body, null, nameof(body));
        Touch(b);
        b.Collides = collides;
        Commit(b);
    }

    /// <summary>
    /// Counts a moving body as changed by the current response without changing it. After a
    /// response the bodies it changed are committed at the contact's time and planned again in the
    /// order they were first changed or involved, and contacts found together afterwards are
    /// handled in that order. The motion world involves a contact's own moving bodies before the
    /// handler's response, in the order the separation moves them (A first, unless A's move was
    /// rejected and A is not a circle while B's was not: then B); a response that will move a
    /// third body calls this to place it in that order. Between steps it does nothing.
    /// </summary>
    /// <param name="body">The body's id.</param>
    /// <exception cref="ArgumentException">The body does not move.</exception>
    public void Involve(BodyId body)
    {
        Body b = Moving(body, null, nameof(body));
        Touch(b);
        Commit(b);
    }

    /// <summary>
    /// Whether a moving body's move was rejected (<see cref="IContactHandler.OnMoveRejected"/>) in
    /// the current or last step, or by a <see cref="Settle"/> since: the body went back to where it
    /// began the step, at rest. Cleared for every body when a step begins.
    /// </summary>
    /// <param name="body">The body's id.</param>
    /// <returns>True when the move was rejected.</returns>
    /// <exception cref="ArgumentException">The body does not move.</exception>
    public bool WasRejected(BodyId body) => Moving(body, null, nameof(body)).Rejected;

    /// <summary>
    /// The caller's tag of a body: a number the caller chooses (0 until set) to find its own record
    /// of the body from a contact (a game's kind of body and its index, say) without decoding the
    /// body's id. The motion world never reads it.
    /// </summary>
    /// <param name="body">The body's id (any body: moving, static or the walls).</param>
    /// <returns>The tag.</returns>
    /// <exception cref="ArgumentException">The id is not one of this motion world's bodies.</exception>
    public int TagOf(BodyId body) => Existing(body, nameof(body)).Tag;

    /// <summary>Sets the caller's tag of a body (see <see cref="TagOf"/>); allowed at any time, it changes nothing of the motion.</summary>
    /// <param name="body">The body's id (any body: moving, static or the walls).</param>
    /// <param name="tag">The tag.</param>
    /// <exception cref="ArgumentException">The id is not one of this motion world's bodies.</exception>
    public void SetTag(BodyId body, int tag) => Existing(body, nameof(body)).Tag = tag;

    /// <summary>Whether a body takes part in contacts (see <see cref="SetCollides"/>).</summary>
    /// <param name="body">The body's id.</param>
    /// <exception cref="ArgumentException">The id is not one of this motion world's bodies.</exception>
    public bool CollidesOf(BodyId body) => Get(body).Collides;

    /// <summary>Tests two bodies at their current poses (for a handler that separates them step by step).</summary>
    /// <param name="bodyA">The first body (moving): the result's translation moves it.</param>
    /// <param name="bodyB">The second body.</param>
    /// <returns>The contact now, or one whose <see cref="Contact.Intersect"/> is false.</returns>
    /// <exception cref="ArgumentException">An id is not one of this motion world's bodies, A does not move, or A and B are the same.</exception>
    public Contact Detect(BodyId bodyA, BodyId bodyB)
    {
        Body a = Moving(bodyA, null, nameof(bodyA));
        Body b = Existing(bodyB, nameof(bodyB));
        if (a == b)
        {
            throw new ArgumentException($"a body cannot be tested against itself ({bodyA})", nameof(bodyB));
        }

        return new Contact(a, b, _schedule.Sampler.Memo.Detect(a, b), Time);
    }

    /// <summary>
    /// Every leaf contact of a fish with another body at their poses now (for a handler that
    /// separates a fish, a compound and non-convex body, along all its overlapping parts): the
    /// fish's leaves (body and fins, tail segments) each tested against the other body's shape or
    /// leaves, written into <paramref name="contacts"/> as
    /// <see cref="FishCollision.DetectAll(FishModel, FishModel, Span{FishContact})"/> writes them
    /// for models laid out at the two poses. The MTVs move the fish. The world's own models are not
    /// touched; nothing is allocated.
    /// </summary>
    /// <param name="fish">The fish's id.</param>
    /// <param name="body">The other body: a fish, a circle or a static body (not the walls or a moving polygon).</param>
    /// <param name="contacts">Where to write the contacts: <see cref="FishCollision.MaxContactsWithFish"/> always suffice.</param>
    /// <returns>The number of contacts written.</returns>
    /// <exception cref="ArgumentException">An id is not one of this motion world's bodies, the first is not a fish, the second is the first, the walls or a moving polygon, or <paramref name="contacts"/> is too short.</exception>
    public int DetectLeaves(BodyId fish, BodyId body, Span<FishContact> contacts)
    {
        Body a = Moving(fish, BodyKind.Fish, nameof(fish));
        Body b = Existing(body, nameof(body));
        if (b == a || b.Kind is BodyKind.Walls or BodyKind.Polygon)
        {
            throw new ArgumentException($"{body} is {(b == a ? "the fish itself" : "a " + b.Kind + " body")}: leaf contacts are found with another fish, a circle or a static body", nameof(body));
        }

        EnsureLoaded();
        return _leaves.Detect(a, b, contacts);
    }

    /// <summary>
    /// Replaces a body (a fish or a static body; not while a step runs) by a static shape at the
    /// same number and with the same tag: the view <see cref="Queries.QueryWorld"/> keeps over a
    /// motion world replaces its bodies so.
    /// </summary>
    /// <returns>The new body's id (a fish's old id no longer names a body; a static body's stays).</returns>
    internal BodyId ReplaceByStatic(BodyId body, in Shape shape)
    {
        Body old = Existing(body, nameof(body));
        if (shape.Kind == ShapeKind.Polygon && shape.AsPolygon().Vertices.Length == 0)
        {
            throw new ArgumentException("polygon is default(ConvexPolygon) and has no vertices", nameof(shape));
        }

        if (_stepping || old.Kind == BodyKind.Walls)
        {
            throw new ArgumentException($"{body} cannot be replaced {(_stepping ? "while a step runs" : "(the walls)")}", nameof(body));
        }

        if (old.Kind == BodyKind.Static)
        {
            // In place: the broad phase takes the statics' boxes again when next loaded.
            old.Reshape(shape);
            Prepare(old);
            _loaded = false;
            QueryMoved(old);
            return old.Handle;
        }

        Body replacement = Body.Static(old.Id, shape);
        Prepare(replacement);
        replacement.Tag = old.Tag;
        replacement.ShapeStamp = old.ShapeStamp + 1;
        _bodies[old.Id] = replacement;
        _loaded = false;
        QueryMoved(replacement);
        return replacement.Handle;
    }

    /// <summary>The shape of a static body.</summary>
    internal Shape StaticShapeOf(BodyId body)
    {
        Body b = Existing(body, nameof(body));
        return b.Kind == BodyKind.Static ? b.Shape : throw new ArgumentException($"{body} is a {b.Kind} body, not a static one", nameof(body));
    }

    internal Body BodyAt(int id) => _bodies[id];

    /// <summary>The id of the body added <paramref name="index"/>-th (tests that walk every body).</summary>
    internal BodyId IdAt(int index) => _bodies[index].Handle;

    /// <summary>The movers (by slot) a response changed since the stages last took them, in the order first changed.</summary>
    internal ReadOnlySpan<int> ChangedBodies => _changed.Items;

    /// <summary>Forgets the changed movers (a stage has taken them).</summary>
    internal void ClearChanged() => _changed.Clear();

    /// <summary>Counts a mover as changed (a stage moved it itself: a rejected move at the end of a step).</summary>
    internal void MarkChanged(int slot) => _changed.Add(slot);

    // Before its state changes in a handler, a body is placed at the handler's time and marked for re-planning.
    private void Touch(Body b)
    {
        if (_stepping && !_changed.Marks[b.Slot])
        {
            b.MoveTo(Time, _schedule.Seconds);
            _changed.Add(b.Slot);
        }
    }

    // After a change in a handler the body moves on from its new state at the handler's time.
    private void Commit(Body b)
    {
        if (_stepping)
        {
            b.Rebase(Time);
        }
        else
        {
            b.Rebase(0.0);
        }
    }

    /// <summary>A body's pose and joints now become where a rejected move of the next step goes back to.</summary>
    internal static void Remember(Body b)
    {
        b.StartPosition = b.Position;
        b.StartHeading = b.Heading;
        b.StartJoint1 = b.Joint1;
        b.StartJoint2 = b.Joint2;
        b.StartJoint3 = b.Joint3;
    }

    private BodyId Add(Body body)
    {
        if (_stepping)
        {
            throw new ArgumentException("bodies cannot be added while a step runs", nameof(body));
        }

        Prepare(body);
        _bodies.Add(body);
        _loaded = false;
        return body.Handle;
    }

    // A new body's motion starts where it is, and it gets its id.
    private void Prepare(Body body)
    {
        body.BasePosition = body.Position;
        body.BaseHeading = body.Heading;
        Remember(body);
        body.KeepStepStart();
        body.Handle = new BodyId(body.Id, _world, _generation, !body.IsMoving);
    }

    private Body Get(BodyId body) => Existing(body, nameof(body));

    // Ids are made only by Add, numbered in the order the bodies were added: an id of this motion
    // world since its last Clear names the body at its index, so the body itself need not be read
    // to check it (a pass over many bodies then reads only what it needs of each).
    private Body Existing(BodyId id, string name)
    {
        int index = id.Index;
        if (id.World != _world || id.Generation != _generation || (uint)index >= (uint)_bodies.Count)
        {
            ThrowNotABody(id, name);
        }

        return _bodies[index];
    }

    // Kept out of Existing so that the check inlines where bodies are looked up.
    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    private void ThrowNotABody(BodyId id, string name) =>
        throw new ArgumentException(
            id.IsNull ? "default(BodyId) names no body: use an id an Add method returned"
            : id.World == _world && id.Generation != _generation ? $"{id} is stale: its body was removed when the motion world was cleared (Clear); use the id Add returned since"
            : $"{id} is not a body of this motion world (it has {_bodies.Count}; an id is valid only in the motion world that returned it)", name);

    private Body Moving(BodyId id, BodyKind? kind, string name)
    {
        Body b = Existing(id, name);
        if (!b.IsMoving || (kind.HasValue && b.Kind != kind.Value))
        {
            throw new ArgumentException($"{id} is a {b.Kind} body, not {(kind.HasValue ? "a " + kind.Value : "a moving")} one", name);
        }

        return b;
    }

    private static void Finite(float value, string name)
    {
        if (!float.IsFinite(value))
        {
            throw new ArgumentException($"must be finite, got {value}", name);
        }
    }

    // The planner and the per-mover sets follow the bodies (allocates only after bodies were added).
    private void EnsureLoaded()
    {
        if (_loaded)
        {
            return;
        }

        var movers = new List<Body>();
        var statics = new List<Body>();
        Body? walls = null;
        foreach (Body b in _bodies)
        {
            if (b.IsMoving)
            {
                b.Slot = movers.Count;
                movers.Add(b);
            }
            else if (b.Kind == BodyKind.Static)
            {
                b.Slot = statics.Count;
                statics.Add(b);
            }
            else
            {
                walls = b;
            }
        }

        int m = movers.Count;
        _schedule.Load([.. movers], [.. statics], walls);
        _islands.Load(m, _schedule.Room);
        _events.Load(m);
        _held.Reserve(_schedule.Room);
        _contacts.Reserve(2 * m);
        _settling.Load(m);
        _changed = new BodySet(m);
        _leaves.Load(_schedule.Planner.MoverBodies);
        _loaded = true;
    }
}
