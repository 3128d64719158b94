using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// A set of bodies — primitive shapes and fish, numbered 0, 1, … in the order added — asked
/// questions: which body a ray enters first (or every body it enters), which bodies overlap a box
/// or a shape, which body is nearest a point. It is a view over a <see cref="MotionWorld"/> that
/// holds the bodies (each shape a static body, each fish a fish at the pose of the model given) and
/// answers the queries (<see cref="MotionWorld.RayCast(Vector2, Vector2)"/> and the others) with the exact tests of
/// <see cref="ShapeQuery"/> and <see cref="CollisionDetector"/>; a body's number is its
/// <see cref="BodyId.Index"/> there.
/// </summary>
/// <remarks>
/// The fish's pose is taken when it is added; after it changes, call <see cref="Refresh"/>.
/// Queries allocate nothing once the world has been queried with its largest spans. Not thread-safe.
/// A program that also moves its bodies can ask its <see cref="MotionWorld"/> directly.
/// </remarks>
public sealed class QueryWorld
{
    private readonly MotionWorld _world;
    private FishModel?[] _fish = new FishModel?[8];
    private BodyId[] _ids = new BodyId[8];
    private BodyId[] _found = [];

    /// <summary>Creates an empty world.</summary>
    /// <param name="broadPhase">The broad phase of the motion world underneath (every kind gives the same answers).</param>
    /// <exception cref="ArgumentException"><paramref name="broadPhase"/> is not a defined kind.</exception>
    public QueryWorld(BroadPhaseKind broadPhase = BroadPhaseKind.DynamicAabbTree)
    {
        _world = new MotionWorld(broadPhase);
    }

    /// <summary>The number of bodies.</summary>
    public int Count { get; private set; }

    /// <summary>Adds a primitive shape.</summary>
    /// <param name="shape">The shape.</param>
    /// <returns>The new body's index.</returns>
    /// <exception cref="ArgumentException">The shape is a default polygon (no vertices).</exception>
    public int Add(in Shape shape) => Added(_world.AddStatic(shape), null);

    /// <summary>Adds a fish (its current pose; call <see cref="Refresh"/> after the pose changes).</summary>
    /// <param name="fish">The fish.</param>
    /// <returns>The new body's index.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="fish"/> is null.</exception>
    public int Add(FishModel fish)
    {
        ArgumentNullException.ThrowIfNull(fish);
        return Added(_world.AddFish(fish.Size, fish.Pose), fish);
    }

    /// <summary>Replaces a body by a primitive shape.</summary>
    /// <param name="body">The body, 0 … <see cref="Count"/> − 1.</param>
    /// <param name="shape">Its new shape.</param>
    /// <exception cref="ArgumentException"><paramref name="body"/> is out of range, or the shape is a default polygon.</exception>
    public void Update(int body, in Shape shape)
    {
        Check(body);
        _ids[body] = _world.ReplaceByStatic(_ids[body], shape);
        _fish[body] = null;
    }

    /// <summary>Takes a fish body's pose again after it changed (a shape body never changes).</summary>
    /// <param name="body">The body, 0 … <see cref="Count"/> − 1.</param>
    /// <exception cref="ArgumentException"><paramref name="body"/> is out of range.</exception>
    public void Refresh(int body)
    {
        Check(body);
        if (_fish[body] is { } fish)
        {
            FishPose pose = fish.Pose;
            _world.SetPose(_ids[body], pose.Position, pose.Heading);
            _world.SetJoints(_ids[body], pose.Joint1, pose.Joint2, pose.Joint3);
        }
    }

    /// <summary>Removes every body.</summary>
    public void Clear()
    {
        _world.Clear();
        Array.Clear(_fish, 0, Count);
        Count = 0;
    }

    /// <summary>The fish of a body, or null when it is a primitive shape.</summary>
    /// <param name="body">The body, 0 … <see cref="Count"/> − 1.</param>
    /// <returns>The fish model (the one added) or null.</returns>
    /// <exception cref="ArgumentException"><paramref name="body"/> is out of range.</exception>
    public FishModel? GetFish(int body)
    {
        Check(body);
        return _fish[body];
    }

    /// <summary>The primitive shape of a body.</summary>
    /// <param name="body">The body, 0 … <see cref="Count"/> − 1.</param>
    /// <returns>The shape.</returns>
    /// <exception cref="ArgumentException"><paramref name="body"/> is out of range.</exception>
    /// <exception cref="InvalidOperationException">The body is a fish.</exception>
    public Shape GetShape(int body)
    {
        Check(body);
        return _fish[body] is null ? _world.StaticShapeOf(_ids[body]) : throw new InvalidOperationException($"body {body} is a fish, not a primitive shape");
    }

    /// <summary>The body the ray from <paramref name="from"/> to <paramref name="to"/> enters first (ties to the lower index).</summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <returns>The body and the entry, or body −1 (see <see cref="ShapeQuery.RayCast(in Shape, Vector2, Vector2)"/> for the rules of a single body).</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public BodyRayHit RayCast(Vector2 from, Vector2 to) => _world.RayCast(from, to);

    /// <summary>Every body the ray enters, nearest first (equal fractions by index).</summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <param name="hits">Receives the first hits, as many as fit.</param>
    /// <returns>The number of bodies entered (may exceed the length of <paramref name="hits"/>).</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public int RayCastAll(Vector2 from, Vector2 to, Span<BodyRayHit> hits) => _world.RayCastAll(from, to, hits);

    /// <summary>The bodies whose interiors overlap a box (touching does not count), ascending.</summary>
    /// <param name="box">The box.</param>
    /// <param name="bodies">Receives the first indices, as many as fit.</param>
    /// <returns>The number of bodies overlapping (may exceed the length of <paramref name="bodies"/>).</returns>
    public int Overlap(in Aabb box, Span<int> bodies)
    {
        Shape shape = box;
        return Overlap(shape, bodies);
    }

    /// <summary>The bodies whose interiors overlap a shape (touching does not count), ascending.</summary>
    /// <param name="shape">The shape.</param>
    /// <param name="bodies">Receives the first indices, as many as fit.</param>
    /// <returns>The number of bodies overlapping (may exceed the length of <paramref name="bodies"/>).</returns>
    public int Overlap(in Shape shape, Span<int> bodies)
    {
        if (_found.Length < bodies.Length)
        {
            _found = new BodyId[bodies.Length];
        }

        int found = _world.Overlap(shape, _found.AsSpan(0, bodies.Length));
        for (int i = 0; i < Math.Min(found, bodies.Length); i++)
        {
            bodies[i] = _found[i].Index;
        }

        return found;
    }

    /// <summary>The body nearest a point (0 inside it; equal distances to the lower index).</summary>
    /// <param name="point">The point, mm.</param>
    /// <returns>The body and the distance, or body −1 when the world is empty.</returns>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public BodyDistance Nearest(Vector2 point) => _world.Nearest(point);

    /// <summary>The bounding box of a primitive shape: its core's extremes grown by its radius.</summary>
    internal static Aabb BoxOf(in Shape shape)
    {
        VertexBuffer8 buffer = default;
        var q = QueryShape.Of(shape, ref buffer);
        Vector2 lo = q.Vertices[0], hi = lo;
        foreach (var p in q.Vertices)
        {
            lo = Vector2.Min(lo, p);
            hi = Vector2.Max(hi, p);
        }

        var r = new Vector2(q.Radius);
        return Aabb.Trusted(lo - r, hi + r);
    }

    private int Added(BodyId id, FishModel? fish)
    {
        if (Count == _ids.Length)
        {
            Array.Resize(ref _ids, Count * 2);
            Array.Resize(ref _fish, Count * 2);
        }

        _ids[Count] = id;
        _fish[Count] = fish;
        return Count++;
    }

    private void Check(int body)
    {
        if ((uint)body >= (uint)Count)
        {
            throw new ArgumentException($"must be a body index 0 … {Count - 1}, got {body}", nameof(body));
        }
    }
}
