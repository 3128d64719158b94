using URWPGSim2D.Collision.Queries;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// The field's borders and obstacles as the collision library sees them, for the demo strategies'
/// planning. Built once per strategy from a snapshot (borders and obstacles never move); the
/// strategy's own <see cref="FieldSensor"/> gives the obstacles' shapes and answers every question.
/// </summary>
/// <remarks>
/// <see cref="Clearance"/> is the signed distance to the nearest border or obstacle. It is sampled
/// on a grid of <see cref="Cell"/> mm: a grid point is measured by the library the first time a
/// lookup needs it (<see cref="Measure"/>), and a lookup interpolates its cell's four corners. It is
/// exact at grid points; between them it reads under 1 mm high where the clearance is 100 mm or
/// more, up to half a cell high close to a corner, and up to half a cell low where two nearest
/// features meet. A plan asks thousands of clearances a cycle: measuring each one exactly made the
/// main job take 2.4 times the CPU time.
/// <see cref="FirstBlocking"/> asks the library's ray cast against each obstacle's bounding box
/// grown by a margin. Nothing is allocated after construction.
/// </remarks>
internal sealed class ObstacleField
{
    /// <summary>Spacing of the clearance grid, mm.</summary>
    public const float Cell = 20f;

    /// <summary>
    /// The most <see cref="Clearance"/> changes per mm moved: √2 in the field (a bilinear blend of
    /// distances, which change at most 1 mm a mm along each axis), 1 + √2 beyond its borders.
    /// </summary>
    public const float MaxSlope = 2.5f;

    private readonly FieldSensor _sensor = new();
    private readonly Shape[] _shapes;
    private readonly Aabb[] _boxes;
    private readonly Vector2 _half;
    private readonly int _columns;
    private readonly int _rows;

    // Grid values by row (Z) then column (X); NaN until measured.
    private readonly float[] _grid;

    /// <summary>The borders and obstacles of a snapshot's field.</summary>
    public ObstacleField(MatchSnapshot snapshot)
    {
        _sensor.Observe(snapshot);
        _half = new Vector2(snapshot.FieldLength, snapshot.FieldWidth) * 0.5f;
        int count = snapshot.Obstacles.Length;
        _shapes = new Shape[count];
        _boxes = new Aabb[count];
        for (int i = 0; i < count; i++)
        {
            _shapes[i] = _sensor.GetShape(SensedBody.Obstacle(i));
            _boxes[i] = BoundsOf(_shapes[i]);
        }

        _columns = (int)MathF.Ceiling(snapshot.FieldLength / Cell) + 1;
        _rows = (int)MathF.Ceiling(snapshot.FieldWidth / Cell) + 1;
        _grid = new float[_columns * _rows];
        _grid.AsSpan().Fill(float.NaN);
    }

    /// <summary>Half the field's length and width, mm.</summary>
    public Vector2 HalfField => _half;

    /// <summary>The number of obstacles.</summary>
    public int Count => _shapes.Length;

    /// <summary>The bounding box of obstacle <paramref name="index"/>.</summary>
    public Aabb Bounds(int index) => _boxes[index];

    /// <summary>
    /// Distance from <paramref name="p"/> to the nearest border or obstacle surface, mm: negative
    /// inside an obstacle (its depth) or outside the field.
    /// </summary>
    public float Clearance(Vector2 p)
    {
        Vector2 inside = Vector2.Clamp(p, -_half, _half);
        float outside = inside == p ? 0f : Vector2.Distance(p, inside);
        float fx = (inside.X + _half.X) / Cell, fz = (inside.Y + _half.Y) / Cell;
        int i = Math.Min((int)fx, _columns - 2), j = Math.Min((int)fz, _rows - 2);
        float tx = fx - i, tz = fz - j;
        float top = Lerp(At(i, j), At(i + 1, j), tx);
        float bottom = Lerp(At(i, j + 1), At(i + 1, j + 1), tx);
        return Lerp(top, bottom, tz) - outside;
    }

    /// <summary>
    /// Corner <paramref name="k"/> (0: −X −Z, 1: +X −Z, 2: −X +Z, 3: +X +Z) of obstacle
    /// <paramref name="index"/>'s bounding box grown by <paramref name="grow"/> mm on every side.
    /// </summary>
    public Vector2 Corner(int index, float grow, int k)
    {
        ref readonly var box = ref _boxes[index];
        Vector2 half = ((box.Max - box.Min) * 0.5f) + new Vector2(grow);
        return box.Center + new Vector2((k & 1) == 0 ? -half.X : half.X, (k & 2) == 0 ? -half.Y : half.Y);
    }

    /// <summary>The signed clearance at <paramref name="p"/> measured by the library, without the grid.</summary>
    public float Measure(Vector2 p)
    {
        Vector2 inside = Vector2.Clamp(p, -_half, _half);
        if (inside != p)
        {
            return -Vector2.Distance(p, inside);
        }

        float clear = _sensor.Clearance(p);
        if (clear > 0f)
        {
            return clear;
        }

        // Inside (or on) an obstacle: as deep as the farthest outline reaches.
        float depth = 0f;
        for (int k = 0; k < _shapes.Length; k++)
        {
            if (ShapeQuery.Distance(_shapes[k], p).Distance <= 0f)
            {
                depth = MathF.Max(depth, DepthIn(_shapes[k], p));
            }
        }

        return -depth;
    }

    /// <summary>The distance from <paramref name="p"/> to obstacle <paramref name="index"/>'s bounding box, mm (0 inside).</summary>
    public float DistanceToBounds(int index, Vector2 p) => ShapeQuery.Distance(_boxes[index], p).Distance;

    /// <summary>Whether the segment <paramref name="a"/>–<paramref name="b"/> keeps <paramref name="margin"/> from every obstacle's bounding box.</summary>
    public bool Free(Vector2 a, Vector2 b, float margin) => FirstBlocking(a, b, margin) < 0;

    /// <summary>
    /// The first obstacle whose bounding box, grown by <paramref name="margin"/>, the segment
    /// <paramref name="a"/>–<paramref name="b"/> passes through, or −1 (touching the grown box does not block).
    /// </summary>
    public int FirstBlocking(Vector2 a, Vector2 b, float margin)
    {
        var grow = new Vector2(margin);
        for (int i = 0; i < _boxes.Length; i++)
        {
            if (Crosses(new Aabb(_boxes[i].Min - grow, _boxes[i].Max + grow), a, b))
            {
                return i;
            }
        }

        return -1;
    }

    private static float Lerp(float a, float b, float t) => a + ((b - a) * t);

    private static bool StrictlyInside(in Aabb box, Vector2 p) => p.X > box.Min.X && p.X < box.Max.X && p.Y > box.Min.Y && p.Y < box.Max.Y;

    // Whether a segment passes through a box's interior: it starts or ends inside, or the library's
    // ray cast enters the box and the middle of the part between entry and exit lies inside (a
    // segment along a side, or through a corner only, does not).
    private static bool Crosses(in Aabb box, Vector2 a, Vector2 b)
    {
        if (StrictlyInside(box, a) || StrictlyInside(box, b))
        {
            return true;
        }

        var enter = ShapeQuery.RayCast(box, a, b);
        if (!enter.Hit)
        {
            return false;
        }

        var leave = ShapeQuery.RayCast(box, b, a);
        float middle = (enter.Fraction + (leave.Hit ? 1f - leave.Fraction : 1f)) * 0.5f;
        return StrictlyInside(box, Vector2.Lerp(a, b, middle));
    }

    private static Aabb BoundsOf(in Shape shape)
    {
        if (shape.Kind == ShapeKind.Circle)
        {
            Circle c = shape.AsCircle();
            return new Aabb(c.Center - new Vector2(c.Radius), c.Center + new Vector2(c.Radius));
        }

        var vertices = shape.AsPolygon().Vertices;
        Vector2 min = vertices[0], max = vertices[0];
        foreach (var v in vertices)
        {
            min = Vector2.Min(min, v);
            max = Vector2.Max(max, v);
        }

        return new Aabb(min, max);
    }

    // The distance from a point inside a shape to its outline.
    private static float DepthIn(in Shape shape, Vector2 p)
    {
        if (shape.Kind == ShapeKind.Circle)
        {
            Circle c = shape.AsCircle();
            return c.Radius - Vector2.Distance(c.Center, p);
        }

        var vertices = shape.AsPolygon().Vertices;
        float depth = float.PositiveInfinity;
        for (int k = 0; k < vertices.Length; k++)
        {
            Shape edge = new Segment(vertices[k], vertices[(k + 1) % vertices.Length]);
            depth = MathF.Min(depth, ShapeQuery.Distance(edge, p).Distance);
        }

        return depth;
    }

    private float At(int i, int j)
    {
        ref float value = ref _grid[(j * _columns) + i];
        if (float.IsNaN(value))
        {
            value = Measure(new Vector2((i * Cell) - _half.X, (j * Cell) - _half.Y));
        }

        return value;
    }
}
