using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Strategies;

/// <summary>
/// Collision queries on what a strategy sees: the field's four borders, the obstacles, the balls
/// and the fish (each fish as the collision model of its eight parts, built from its
/// <see cref="FishView"/>). Asks where a ray first enters a body (<see cref="RayCast"/>), which
/// bodies overlap a shape (<see cref="Overlap"/>), which body is nearest a point
/// (<see cref="Nearest"/>) and how far apart two bodies are (<see cref="Distance(SensedBody, SensedBody)"/>).
/// The answers are those of the collision library's queries (<see cref="ShapeQuery"/> over a
/// <see cref="QueryWorld"/> per kind of body), so they hold to its precision: exact ray casts,
/// distances to float round-off.
/// </summary>
/// <remarks>
/// Make one sensor per strategy and call <see cref="Observe"/> with the snapshot at the start of
/// each cycle's decision; queries answer about the snapshot last observed. Observing a snapshot of
/// the same match allocates nothing (the fish models and the obstacles' shapes are built the first
/// time, and again only when the field, the obstacles or a fish's size change); queries allocate
/// nothing. Plane vectors, mm (X = world X, Y = world Z), as in the views. Not thread-safe.
/// </remarks>
public sealed partial class FieldSensor
{
    private const int KindCount = 4;
    private readonly QueryWorld[] _worlds = [new(), new(), new(), new()];

    // The shapes of the borders, obstacles and balls, by slot (the worlds hold copies for their broad phases).
    private readonly Shape[][] _shapes = [new Shape[4], [], []];

    // Their bounding circles, by slot: a body whose circle is far enough is not measured.
    private readonly Circle[][] _bounds = [new Circle[4], [], []];
    private ObstacleView[] _obstacles = [];
    private FishModel[] _models = [];
    private BodyRayHit[] _rayHits = new BodyRayHit[8];
    private int[] _indices = new int[8];
    private Vector2 _field = new(float.NaN);
    private bool _observed;

    /// <summary>The cycle of the snapshot last observed (−1 before the first).</summary>
    public int Cycle { get; private set; } = -1;

    /// <summary>Takes the bodies of a snapshot: the queries answer about it until the next call.</summary>
    /// <param name="snapshot">The snapshot the strategy decides from.</param>
    /// <exception cref="ArgumentNullException"><paramref name="snapshot"/> is null.</exception>
    /// <exception cref="ArgumentException">A view has a size no body can have (a fish, ball or obstacle of zero or non-finite size, a non-finite position).</exception>
    public void Observe(MatchSnapshot snapshot)
    {
        ArgumentNullException.ThrowIfNull(snapshot);
        var field = new Vector2(snapshot.FieldLength, snapshot.FieldWidth);
        if (field != _field)
        {
            TakeWalls(field * 0.5f);
            _field = field;
        }

        if (!snapshot.Obstacles.SequenceEqual(_obstacles))
        {
            TakeObstacles(snapshot.Obstacles);
        }

        TakeBalls(snapshot.Balls);
        TakeFish(snapshot.Fish);
        Cycle = snapshot.Cycle;
        _observed = true;
    }

    /// <summary>The collision model of a fish as last observed (its eight parts at its pose): for the library's own queries.</summary>
    /// <param name="index">The fish's index in <see cref="MatchSnapshot.Fish"/>.</param>
    /// <returns>The model (the same instance every cycle, moved to the fish's new pose by <see cref="Observe"/>).</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException"><paramref name="index"/> is not a fish of the snapshot.</exception>
    public FishModel GetFish(int index)
    {
        Check(SensedBody.Fish(index), nameof(index));
        return _models[index];
    }

    /// <summary>The shape of a border, obstacle or ball as last observed: for the library's own queries.</summary>
    /// <param name="body">The body (not a fish: see <see cref="GetFish"/>).</param>
    /// <returns>A border's segment, an obstacle's polygon or circle, a ball's circle.</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException"><paramref name="body"/> is not a body of the snapshot, or is a fish.</exception>
    public Shape GetShape(SensedBody body)
    {
        Check(body, nameof(body));
        return body.Kind != SensedKind.Fish
            ? _shapes[Slot(body.Kind)][body.Index]
            : throw new ArgumentException($"must be a border, obstacle or ball, got {body} (a fish has eight parts: use GetFish)", nameof(body));
    }

    private static int Slot(SensedKind kind) => (int)kind - 1;

    private static SensedKind KindOf(int slot) => (SensedKind)(slot + 1);

    private static Vector2 Rotate(Vector2 v, float cos, float sin) => new((v.X * cos) - (v.Y * sin), (v.X * sin) + (v.Y * cos));

    private void TakeWalls(Vector2 half)
    {
        // The original's numbering: 0 top (Z = −W/2), 1 right, 2 bottom, 3 left.
        var walls = _worlds[Slot(SensedKind.Wall)];
        walls.Clear();
        Vector2 topLeft = -half, topRight = new(half.X, -half.Y), bottomRight = half, bottomLeft = new(-half.X, half.Y);
        var shapes = _shapes[Slot(SensedKind.Wall)];
        shapes[0] = new Segment(topLeft, topRight);
        shapes[1] = new Segment(topRight, bottomRight);
        shapes[2] = new Segment(bottomRight, bottomLeft);
        shapes[3] = new Segment(bottomLeft, topLeft);
        for (int i = 0; i < shapes.Length; i++)
        {
            walls.Add(shapes[i]);
            _bounds[Slot(SensedKind.Wall)][i] = shapes[i].BoundingCircle;
        }
    }

    private void TakeObstacles(ReadOnlySpan<ObstacleView> obstacles)
    {
        var world = _worlds[Slot(SensedKind.Obstacle)];
        world.Clear();
        _obstacles = obstacles.ToArray();
        var shapes = _shapes[Slot(SensedKind.Obstacle)] = new Shape[obstacles.Length];
        var bounds = _bounds[Slot(SensedKind.Obstacle)] = new Circle[obstacles.Length];
        Span<Vector2> corners = stackalloc Vector2[4];
        for (int i = 0; i < obstacles.Length; i++)
        {
            ref readonly var o = ref obstacles[i];
            if (o.Kind == ObstacleKind.Round)
            {
                shapes[i] = new Circle(o.Center, o.Radius);
                bounds[i] = shapes[i].BoundingCircle;
                world.Add(shapes[i]);
                continue;
            }

            float cos = MathF.Cos(o.Heading), sin = MathF.Sin(o.Heading);
            Vector2 half = new(o.Length * 0.5f, o.Width * 0.5f);
            corners[0] = o.Center + Rotate(new Vector2(-half.X, -half.Y), cos, sin);
            corners[1] = o.Center + Rotate(new Vector2(half.X, -half.Y), cos, sin);
            corners[2] = o.Center + Rotate(half, cos, sin);
            corners[3] = o.Center + Rotate(new Vector2(-half.X, half.Y), cos, sin);
            shapes[i] = new ConvexPolygon(corners);
            bounds[i] = shapes[i].BoundingCircle;
            world.Add(shapes[i]);
        }

        Reserve(obstacles.Length);
    }

    private void TakeBalls(ReadOnlySpan<BallView> balls)
    {
        var world = _worlds[Slot(SensedKind.Ball)];
        var shapes = _shapes[Slot(SensedKind.Ball)];
        if (balls.Length != shapes.Length)
        {
            world.Clear();
            shapes = _shapes[Slot(SensedKind.Ball)] = new Shape[balls.Length];
            _bounds[Slot(SensedKind.Ball)] = new Circle[balls.Length];
            for (int i = 0; i < balls.Length; i++)
            {
                var circle = new Circle(balls[i].Position, balls[i].Radius);
                shapes[i] = circle;
                _bounds[Slot(SensedKind.Ball)][i] = circle;
                world.Add(shapes[i]);
            }

            Reserve(balls.Length);
            return;
        }

        var bounds = _bounds[Slot(SensedKind.Ball)];
        for (int i = 0; i < balls.Length; i++)
        {
            var circle = new Circle(balls[i].Position, balls[i].Radius);
            shapes[i] = circle;
            bounds[i] = circle;
            world.Update(i, shapes[i]);
        }
    }

    private void TakeFish(ReadOnlySpan<FishView> fish)
    {
        var world = _worlds[Slot(SensedKind.Fish)];
        bool rebuild = fish.Length != _models.Length;
        if (rebuild)
        {
            Array.Resize(ref _models, fish.Length);
            Reserve(fish.Length);
        }

        for (int i = 0; i < fish.Length; i++)
        {
            ref readonly var f = ref fish[i];
            var pose = new FishPose(f.Position, f.Heading, f.Joint1, f.Joint2, f.Joint3);
            var model = _models[i];
            if (model is null || !SameSize(model.Size, f))
            {
                _models[i] = new FishModel(new FishSize(f.BodyLength, f.Width, f.HeadLength, f.TailLength1, f.TailLength2, f.TailLength3), pose);
                rebuild = true;
            }
            else
            {
                model.SetPose(pose);
                if (!rebuild)
                {
                    world.Refresh(i);
                }
            }
        }

        if (rebuild)
        {
            world.Clear();
            foreach (var model in _models)
            {
                world.Add(model);
            }
        }
    }

    private static bool SameSize(FishSize size, in FishView f) =>
        size.Length == f.BodyLength && size.Width == f.Width && size.Head == f.HeadLength
        && size.Joint1 == f.TailLength1 && size.Joint2 == f.TailLength2 && size.Joint3 == f.TailLength3;

    // The scratch buffers hold every body of the largest world.
    private void Reserve(int count)
    {
        if (count > _rayHits.Length)
        {
            _rayHits = new BodyRayHit[count];
            _indices = new int[count];
        }
    }
}
