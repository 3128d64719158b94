using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// A set of bodies — primitive shapes and fish, numbered 0, 1, … in the order added — asked
/// questions through a broad phase: which body a ray enters first (or every body it enters),
/// which bodies overlap a box or a shape, which body is nearest a point. Each query takes the
/// broad phase's candidates (bodies whose bounding boxes meet the query's box) and answers with
/// the exact tests of <see cref="ShapeQuery"/> and <see cref="CollisionDetector"/>.
/// </summary>
/// <remarks>
/// A body's box is taken when it is added or <see cref="Update(int, in Shape)">updated</see>;
/// after a fish's pose changes, call <see cref="Refresh"/>. Queries allocate nothing once the
/// world has been queried at its largest size. Not thread-safe.
/// </remarks>
public sealed class QueryWorld
{
    private readonly IBroadPhase _broadPhase;
    private readonly IndexList _candidates = new();
    private Shape[] _shapes = new Shape[8];
    private FishModel?[] _fish = new FishModel?[8];
    private Aabb[] _boxes = new Aabb[8];
    private bool _rebuild;

    /// <summary>Creates an empty world.</summary>
    /// <param name="broadPhase">The broad phase that finds the candidates (every kind gives the same answers).</param>
    /// <exception cref="ArgumentException"><paramref name="broadPhase"/> is not a defined kind.</exception>
    public QueryWorld(BroadPhaseKind broadPhase = BroadPhaseKind.DynamicAabbTree)
    {
        _broadPhase = BroadPhaseFactory.Create(broadPhase, nameof(broadPhase));
    }

    /// <summary>The number of bodies.</summary>
    public int Count { get; private set; }

    /// <summary>Adds a primitive shape.</summary>
    /// <param name="shape">The shape.</param>
    /// <returns>The new body's index.</returns>
    public int Add(in Shape shape)
    {
        int body = Grow();
        _shapes[body] = shape;
        _boxes[body] = BoxOf(shape);
        return body;
    }

    /// <summary>Adds a fish (its current pose; call <see cref="Refresh"/> after the pose changes).</summary>
    /// <param name="fish">The fish.</param>
    /// <returns>The new body's index.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="fish"/> is null.</exception>
    public int Add(FishModel fish)
    {
        ArgumentNullException.ThrowIfNull(fish);
        int body = Grow();
        _fish[body] = fish;
        _boxes[body] = fish.Bounds;
        return body;
    }

    /// <summary>Replaces a body by a primitive shape.</summary>
    /// <param name="body">The body, 0 … <see cref="Count"/> − 1.</param>
    /// <param name="shape">Its new shape.</param>
    /// <exception cref="ArgumentException"><paramref name="body"/> is out of range.</exception>
    public void Update(int body, in Shape shape)
    {
        Check(body);
        _fish[body] = null;
        _shapes[body] = shape;
        Moved(body, BoxOf(shape));
    }

    /// <summary>Takes a fish body's box again after its pose changed (or a shape body's, which never changes).</summary>
    /// <param name="body">The body, 0 … <see cref="Count"/> − 1.</param>
    /// <exception cref="ArgumentException"><paramref name="body"/> is out of range.</exception>
    public void Refresh(int body)
    {
        Check(body);
        Moved(body, _fish[body] is { } fish ? fish.Bounds : BoxOf(_shapes[body]));
    }

    /// <summary>Removes every body.</summary>
    public void Clear()
    {
        Array.Clear(_fish, 0, Count);
        Count = 0;
        _rebuild = true;
    }

    /// <summary>The fish of a body, or null when it is a primitive shape.</summary>
    /// <param name="body">The body, 0 … <see cref="Count"/> − 1.</param>
    /// <returns>The fish model or null.</returns>
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
        return _fish[body] is null ? _shapes[body] : throw new InvalidOperationException($"body {body} is a fish, not a primitive shape");
    }

    /// <summary>The body the ray from <paramref name="from"/> to <paramref name="to"/> enters first (ties to the lower index).</summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <returns>The body and the entry, or body −1 (see <see cref="ShapeQuery.RayCast(in Shape, Vector2, Vector2)"/> for the rules of a single body).</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public BodyRayHit RayCast(Vector2 from, Vector2 to)
    {
        ShapeQuery.CheckRay(from, to);
        Candidates(Aabb.Trusted(Vector2.Min(from, to), Vector2.Max(from, to)));
        var best = new BodyRayHit(-1, default);
        foreach (int body in _candidates.Items)
        {
            var hit = ShapeQuery.RayCast(BodyAt(body), from, to);
            if (hit.Hit && (best.Body < 0 || hit.Fraction < best.Result.Fraction))
            {
                best = new BodyRayHit(body, hit);
            }
        }

        return best;
    }

    /// <summary>Every body the ray enters, nearest first (equal fractions by index).</summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <param name="hits">Receives the first hits, as many as fit.</param>
    /// <returns>The number of bodies entered (may exceed the length of <paramref name="hits"/>).</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public int RayCastAll(Vector2 from, Vector2 to, Span<BodyRayHit> hits)
    {
        ShapeQuery.CheckRay(from, to);
        Candidates(Aabb.Trusted(Vector2.Min(from, to), Vector2.Max(from, to)));
        int found = 0;
        foreach (int body in _candidates.Items)
        {
            var hit = ShapeQuery.RayCast(BodyAt(body), from, to);
            if (!hit.Hit)
            {
                continue;
            }

            // Insertion into the sorted prefix; hits past the span's end are counted, not kept.
            int at = Math.Min(found, hits.Length);
            while (at > 0 && hits[at - 1].Result.Fraction > hit.Fraction)
            {
                if (at < hits.Length)
                {
                    hits[at] = hits[at - 1];
                }

                at--;
            }

            if (at < hits.Length)
            {
                hits[at] = new BodyRayHit(body, hit);
            }

            found++;
        }

        return found;
    }

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
        Candidates(BoxOf(shape));
        int found = 0;
        var query = new QueryBody(in shape);
        foreach (int body in _candidates.Items)
        {
            if (QueryBody.Contact(query, BodyAt(body)).Intersect)
            {
                if (found < bodies.Length)
                {
                    bodies[found] = body;
                }

                found++;
            }
        }

        return found;
    }

    /// <summary>The body nearest a point (0 inside it; equal distances to the lower index).</summary>
    /// <param name="point">The point, mm.</param>
    /// <returns>The body and the distance, or body −1 when the world is empty.</returns>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public BodyDistance Nearest(Vector2 point)
    {
        Guard.Finite(point, nameof(point));
        if (Count == 0)
        {
            return new BodyDistance(-1, default);
        }

        // Grow a box around the point until it meets a body; the nearest body then lies within
        // the distance of the nearest candidate, so one more query of that reach settles it.
        float reach = 16f;
        Rebuild();
        while (true)
        {
            Candidates(Around(point, reach));
            if (_candidates.Count > 0 || reach > 1e30f)
            {
                break;
            }

            reach *= 4f;
        }

        float bound = float.PositiveInfinity;
        foreach (int body in _candidates.Items)
        {
            bound = MathF.Min(bound, ShapeQuery.ToPoint(BodyAt(body), point).Distance);
        }

        Candidates(Around(point, bound * 1.0001f + 1e-3f));
        var best = new BodyDistance(-1, default);
        foreach (int body in _candidates.Items)
        {
            var d = ShapeQuery.ToPoint(BodyAt(body), point);
            if (best.Body < 0 || d.Distance < best.Result.Distance)
            {
                best = new BodyDistance(body, d);
            }
        }

        return best;
    }

    internal QueryBody BodyAt(int body) =>
        _fish[body] is { } fish ? new QueryBody(fish) : new QueryBody(ref _shapes[body]);

    private static Aabb Around(Vector2 point, float reach) =>
        Aabb.Trusted(point - new Vector2(reach), point + new Vector2(reach));

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

    private void Candidates(in Aabb box)
    {
        Rebuild();
        _broadPhase.Query(box, _candidates);
    }

    private void Rebuild()
    {
        if (_rebuild)
        {
            _broadPhase.Reset(_boxes.AsSpan(0, Count), Count);
            _rebuild = false;
        }
    }

    private void Moved(int body, in Aabb box)
    {
        _boxes[body] = box;
        if (!_rebuild)
        {
            _broadPhase.Move(body, box);
        }
    }

    private int Grow()
    {
        if (Count == _shapes.Length)
        {
            Array.Resize(ref _shapes, Count * 2);
            Array.Resize(ref _fish, Count * 2);
            Array.Resize(ref _boxes, Count * 2);
        }

        _rebuild = true;
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
