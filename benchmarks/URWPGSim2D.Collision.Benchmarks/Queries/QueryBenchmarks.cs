using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Queries;

namespace URWPGSim2D.Collision.Benchmarks.Queries;

/// <summary>
/// The cost of each query over a fixed random set (512 cases, seed 27), reported per query:
/// distance, ray cast and shape cast between convex polygons of 4 to 8 vertices that are apart,
/// the same with a circle and with a fish, and the world queries over 60 bodies and over 10,000
/// (small polygons spread over 20 m × 20 m, each ray up to 1.5 m long, each box 200 mm).
/// </summary>
[MemoryDiagnoser]
public class QueryBenchmarks
{
    private const int Cases = 512;
    private const int LargeWorld = 10_000;
    private ConvexPolygon[] _a = [], _b = [];
    private Shape[] _sa = [], _sb = [];
    private Circle[] _circles = [];
    private Vector2[] _from = [], _to = [], _move = [];
    private FishModel _fish = null!;
    private QueryWorld _world = null!;
    private QueryWorld _large = null!;
    private Vector2[] _largeFrom = [], _largeTo = [];
    private readonly BodyRayHit[] _hits = new BodyRayHit[64];
    private readonly int[] _found = new int[64];

    /// <summary>Builds the cases.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var rng = new Random(27);
        _a = new ConvexPolygon[Cases];
        _b = new ConvexPolygon[Cases];
        _sa = new Shape[Cases];
        _sb = new Shape[Cases];
        _circles = new Circle[Cases];
        _from = new Vector2[Cases];
        _to = new Vector2[Cases];
        _move = new Vector2[Cases];
        for (int i = 0; i < Cases; i++)
        {
            Vector2 ca = Point(rng, 2000f);
            float sizeA = Range(rng, 50f, 400f), sizeB = Range(rng, 50f, 400f);
            float angle = Range(rng, 0f, 2f * MathF.PI);
            Vector2 cb = ca + (new Vector2(MathF.Cos(angle), MathF.Sin(angle)) * ((sizeA + sizeB) / 2f * Range(rng, 1.05f, 2f)));
            _a[i] = Polygon(rng, ca, sizeA);
            _b[i] = Polygon(rng, cb, sizeB);
            _sa[i] = _a[i];
            _sb[i] = _b[i];
            _circles[i] = new Circle(ca, sizeA / 2f);
            float phase = Range(rng, 0f, 2f * MathF.PI);
            Vector2 u = new(MathF.Cos(phase), MathF.Sin(phase));
            _from[i] = cb + (u * sizeB * 1.5f);
            _to[i] = cb - (u * sizeB * 1.5f) + Point(rng, sizeB / 3f);
            _move[i] = (cb - ca) * 1.5f;
        }

        _fish = new FishModel(FishSize.Default, new FishPose(Vector2.Zero, 0.4f, 0.3f, -0.2f, 0.5f));
        _world = new QueryWorld(BroadPhaseKind.DynamicAabbTree);
        for (int i = 0; i < 60; i++)
        {
            _world.Add(_sb[i]);
        }

        _large = new QueryWorld(BroadPhaseKind.DynamicAabbTree);
        for (int i = 0; i < LargeWorld; i++)
        {
            _large.Add(Polygon(rng, Point(rng, 10000f), Range(rng, 30f, 120f)));
        }

        _largeFrom = new Vector2[Cases];
        _largeTo = new Vector2[Cases];
        for (int i = 0; i < Cases; i++)
        {
            _largeFrom[i] = Point(rng, 10000f);
            _largeTo[i] = _largeFrom[i] + Point(rng, 1500f / MathF.Sqrt(2f));
        }
    }

    /// <summary>Distance between two polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public float DistancePolygons()
    {
        float s = 0f;
        for (int i = 0; i < Cases; i++)
        {
            s += ShapeQuery.Distance(_a[i], _b[i]).Distance;
        }

        return s;
    }

    /// <summary>Distance between a circle and a polygon, through <see cref="Shape"/> (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public float DistanceCirclePolygon()
    {
        float s = 0f;
        for (int i = 0; i < Cases; i++)
        {
            s += ShapeQuery.Distance(_circles[i], _sb[i]).Distance;
        }

        return s;
    }

    /// <summary>Distance between a fish and a polygon (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public float DistanceFishPolygon()
    {
        float s = 0f;
        for (int i = 0; i < Cases; i++)
        {
            s += ShapeQuery.Distance(_fish, _sb[i]).Distance;
        }

        return s;
    }

    /// <summary>Ray cast against a polygon (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public float RayCastPolygon()
    {
        float s = 0f;
        for (int i = 0; i < Cases; i++)
        {
            s += ShapeQuery.RayCast(_b[i], _from[i], _to[i]).Fraction;
        }

        return s;
    }

    /// <summary>Ray cast against a fish (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public float RayCastFish()
    {
        float s = 0f;
        for (int i = 0; i < Cases; i++)
        {
            s += ShapeQuery.RayCast(_fish, _from[i] - _b[i].BoundingCircle.Center, _to[i] - _b[i].BoundingCircle.Center).Fraction;
        }

        return s;
    }

    /// <summary>Shape cast of a polygon against a polygon (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public float CastPolygons()
    {
        float s = 0f;
        for (int i = 0; i < Cases; i++)
        {
            s += ShapeQuery.Cast(_sa[i], _move[i], _sb[i]).Fraction;
        }

        return s;
    }

    /// <summary>Closest ray hit over a world of 60 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int WorldRayCast()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _world.RayCast(_from[i], _to[i]).Body;
        }

        return s;
    }

    /// <summary>The body nearest a point in a world of 60 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int WorldNearest()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _world.Nearest(_from[i]).Body;
        }

        return s;
    }

    /// <summary>Every ray hit over a world of 60 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int WorldRayCastAll()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _world.RayCastAll(_from[i], _to[i], _hits);
        }

        return s;
    }

    /// <summary>The bodies overlapping a box in a world of 60 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int WorldOverlap()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _world.Overlap(new Aabb(_from[i] - new Vector2(100f), _from[i] + new Vector2(100f)), _found);
        }

        return s;
    }

    /// <summary>Closest ray hit over a world of 10,000 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int LargeWorldRayCast()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _large.RayCast(_largeFrom[i], _largeTo[i]).Body;
        }

        return s;
    }

    /// <summary>Every ray hit over a world of 10,000 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int LargeWorldRayCastAll()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _large.RayCastAll(_largeFrom[i], _largeTo[i], _hits);
        }

        return s;
    }

    /// <summary>The bodies overlapping a box in a world of 10,000 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int LargeWorldOverlap()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _large.Overlap(new Aabb(_largeFrom[i] - new Vector2(100f), _largeFrom[i] + new Vector2(100f)), _found);
        }

        return s;
    }

    /// <summary>The body nearest a point in a world of 10,000 polygons (per query).</summary>
    [Benchmark(OperationsPerInvoke = Cases)]
    public int LargeWorldNearest()
    {
        int s = 0;
        for (int i = 0; i < Cases; i++)
        {
            s += _large.Nearest(_largeFrom[i]).Body;
        }

        return s;
    }

    private static float Range(Random rng, float lo, float hi) => lo + ((hi - lo) * (float)rng.NextDouble());

    private static Vector2 Point(Random rng, float half) => new(Range(rng, -half, half), Range(rng, -half, half));

    // 4 to 8 vertices on an ellipse at sorted random angles at least 0.25 rad apart.
    private static ConvexPolygon Polygon(Random rng, Vector2 centre, float size)
    {
        int n = rng.Next(4, 9);
        var angles = new float[n];
        while (true)
        {
            for (int i = 0; i < n; i++)
            {
                angles[i] = Range(rng, 0f, 2f * MathF.PI);
            }

            Array.Sort(angles);
            bool spread = true;
            for (int i = 0; i < n; i++)
            {
                float gap = (angles[(i + 1) % n] - angles[i] + (2f * MathF.PI)) % (2f * MathF.PI);
                spread &= gap > 0.25f && gap < MathF.PI - 0.1f;
            }

            if (spread)
            {
                break;
            }
        }

        float a = size / 2f, b = a * Range(rng, 0.4f, 1f), rot = Range(rng, 0f, MathF.PI);
        var v = new Vector2[n];
        for (int i = 0; i < n; i++)
        {
            float x = a * MathF.Cos(angles[i]), y = b * MathF.Sin(angles[i]);
            v[i] = centre + new Vector2((x * MathF.Cos(rot)) - (y * MathF.Sin(rot)), (x * MathF.Sin(rot)) + (y * MathF.Cos(rot)));
        }

        return new ConvexPolygon(v);
    }
}
