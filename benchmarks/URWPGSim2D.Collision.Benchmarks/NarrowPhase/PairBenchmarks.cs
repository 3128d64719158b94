extern alias baseline;

using System;
using System.Numerics;
using URWPGSim2D.Collision.Shapes;
using FrozenDetector = baseline::URWPGSim2D.Collision.CollisionDetector;
using FrozenResult = baseline::URWPGSim2D.Collision.CollisionDetectionResult;
using FrozenShapes = baseline::URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Benchmarks.NarrowPhase;

/// <summary>
/// Single-pair narrow-phase costs with the full result (MTV, normal, action point), each category
/// against the same pair in the frozen baseline (the library of the commit tagged
/// <c>benchmark-baseline</c>, through its own <c>CollisionDetector</c>), measured in the same run: the speed-up column is baseline median / current median. The random
/// sets (1,000 pairs, fixed seed) report the cost per pair.
/// </summary>
[Config(typeof(BaselineConfig))]
public class PairBenchmarks
{
    // What each benchmark computes is kept here (a void benchmark's result must stay alive, and
    // BenchmarkDotNet's generated project cannot name a type that the library and the frozen
    // baseline both define).
    private FrozenResult _frozenResult;
    private CollisionDetectionResult _result;

    private const int SetSize = 1_000;
    private Circle _circleA, _circleB;
    private ConvexPolygon _boxA, _boxB, _octA, _octB, _polygon;
    private KDop8 _kdopA, _kdopB;
    private Aabb _aabbA, _aabbB;
    private Vector2[] _boxArrayA = [], _boxArrayB = [], _octArrayA = [], _octArrayB = [];
    private ConvexPolygon[] _setA = [], _setB = [], _apartA = [], _apartB = [], _circlePolygons = [];
    private Circle[] _circles = [];
    private FrozenShapes.Circle _frozenCircleA;
    private FrozenShapes.ConvexPolygon _frozenBoxA, _frozenBoxB, _frozenOctA, _frozenOctB, _frozenPolygon;
    private FrozenShapes.ConvexPolygon[] _frozenSetA = [], _frozenSetB = [], _frozenApartA = [], _frozenApartB = [], _frozenCirclePolygons = [];
    private FrozenShapes.Circle[] _frozenCircles = [];

    /// <summary>Builds overlapping pairs of every benchmarked kind and the random sets.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _circleA = new Circle(new Vector2(0f, 0f), 58f);
        _circleB = new Circle(new Vector2(90f, 20f), 58f);
        _boxArrayA = Box(new Vector2(0f, 0f), 100f, 60f, 0.3f);
        _boxArrayB = Box(new Vector2(80f, 30f), 100f, 60f, -0.4f);
        _boxA = new ConvexPolygon(_boxArrayA);
        _boxB = new ConvexPolygon(_boxArrayB);
        _octArrayA = Regular(new Vector2(0f, 0f), 60f, 8, 0.1f);
        _octArrayB = Regular(new Vector2(100f, 25f), 60f, 8, 0.5f);
        _octA = new ConvexPolygon(_octArrayA);
        _octB = new ConvexPolygon(_octArrayB);
        _polygon = new ConvexPolygon(Regular(new Vector2(70f, 10f), 50f, 6, 0.2f));
        _kdopA = KDop8.FromPoints(_octArrayA);
        _kdopB = KDop8.FromPoints(_octArrayB);
        _aabbA = new Aabb(new Vector2(-50f, -30f), new Vector2(50f, 30f));
        _aabbB = new Aabb(new Vector2(20f, 10f), new Vector2(120f, 70f));
        (_setA, _setB) = RandomPolygonPairs(new Random(10), overlapping: true);
        (_apartA, _apartB) = RandomPolygonPairs(new Random(11), overlapping: false);
        (_circles, _circlePolygons) = RandomCirclePolygonPairs(new Random(12));

        // The same shapes for the frozen baseline.
        _frozenCircleA = Frozen(_circleA);
        (_frozenBoxA, _frozenBoxB, _frozenOctA, _frozenOctB, _frozenPolygon) = (Frozen(_boxA), Frozen(_boxB), Frozen(_octA), Frozen(_octB), Frozen(_polygon));
        (_frozenSetA, _frozenSetB) = (Array.ConvertAll(_setA, Frozen), Array.ConvertAll(_setB, Frozen));
        (_frozenApartA, _frozenApartB) = (Array.ConvertAll(_apartA, Frozen), Array.ConvertAll(_apartB, Frozen));
        (_frozenCircles, _frozenCirclePolygons) = (Array.ConvertAll(_circles, Frozen), Array.ConvertAll(_circlePolygons, Frozen));
    }

    /// <summary>Circle against circle (no baseline: unchanged kernel, for scale).</summary>
    [Benchmark]
    [BenchmarkCategory("circle-circle")]
    public void CircleCircle() => _result = CollisionDetector.Detect(_circleA, _circleB);

    /// <summary>Two rotated boxes (4-gons), full SAT with MTV and action point.</summary>
    [Benchmark]
    [BenchmarkCategory("box-box")]
    public void BoxBox() => _result = CollisionDetector.Detect(_boxA, _boxB);

    /// <summary>The same two boxes through the frozen SAT.</summary>
    [Benchmark(Baseline = true)]
    [BenchmarkCategory("box-box")]
    public void BoxBoxBaseline() => _frozenResult = FrozenDetector.Detect(_frozenBoxA, _frozenBoxB);

    /// <summary>Textbook allocating SAT on the same two boxes (MTV only, no action point).</summary>
    [Benchmark]
    [BenchmarkCategory("box-box")]
    public bool TextbookBoxBox() => TextbookSat.Test(_boxArrayA, _boxArrayB, out _);

    /// <summary>Two regular octagons as general polygons.</summary>
    [Benchmark]
    [BenchmarkCategory("octagon-octagon")]
    public void OctagonOctagon() => _result = CollisionDetector.Detect(_octA, _octB);

    /// <summary>The same two octagons through the frozen SAT.</summary>
    [Benchmark(Baseline = true)]
    [BenchmarkCategory("octagon-octagon")]
    public void OctagonOctagonBaseline() => _frozenResult = FrozenDetector.Detect(_frozenOctA, _frozenOctB);

    /// <summary>Textbook allocating SAT on the same two octagons.</summary>
    [Benchmark]
    [BenchmarkCategory("octagon-octagon")]
    public bool TextbookOctagonOctagon() => TextbookSat.Test(_octArrayA, _octArrayB, out _);

    /// <summary>Circle against hexagon by Voronoi regions.</summary>
    [Benchmark]
    [BenchmarkCategory("circle-hexagon")]
    public void CirclePolygon() => _result = CollisionDetector.Detect(_circleA, _polygon);

    /// <summary>The same circle and hexagon through the frozen kernel.</summary>
    [Benchmark(Baseline = true)]
    [BenchmarkCategory("circle-hexagon")]
    public void CirclePolygonBaseline() => _frozenResult = FrozenDetector.Detect(_frozenCircleA, _frozenPolygon);

    /// <summary>1,000 random overlapping convex polygon pairs (3–8 vertices), per pair.</summary>
    [Benchmark(OperationsPerInvoke = SetSize)]
    [BenchmarkCategory("random polygon pairs, overlapping")]
    public float RandomPolygons()
    {
        float sum = 0f;
        for (int i = 0; i < _setA.Length; i++)
        {
            sum += CollisionDetector.Detect(_setA[i], _setB[i]).MinimumTranslationVector.X;
        }

        return sum;
    }

    /// <summary>The same 1,000 pairs through the frozen SAT.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = SetSize)]
    [BenchmarkCategory("random polygon pairs, overlapping")]
    public float RandomPolygonsBaseline()
    {
        float sum = 0f;
        for (int i = 0; i < _frozenSetA.Length; i++)
        {
            sum += FrozenDetector.Detect(_frozenSetA[i], _frozenSetB[i]).MinimumTranslationVector.X;
        }

        return sum;
    }

    /// <summary>1,000 random separated convex polygon pairs whose bounding circles overlap, per pair.</summary>
    [Benchmark(OperationsPerInvoke = SetSize)]
    [BenchmarkCategory("random polygon pairs, separated")]
    public float SeparatedPolygons()
    {
        float sum = 0f;
        for (int i = 0; i < _apartA.Length; i++)
        {
            sum += CollisionDetector.Detect(_apartA[i], _apartB[i]).Intersect ? 1f : 0f;
        }

        return sum;
    }

    /// <summary>The same separated pairs through the frozen SAT.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = SetSize)]
    [BenchmarkCategory("random polygon pairs, separated")]
    public float SeparatedPolygonsBaseline()
    {
        float sum = 0f;
        for (int i = 0; i < _apartA.Length; i++)
        {
            sum += FrozenDetector.Detect(_frozenApartA[i], _frozenApartB[i]).Intersect ? 1f : 0f;
        }

        return sum;
    }

    /// <summary>1,000 random circle–polygon pairs (half overlapping), per pair.</summary>
    [Benchmark(OperationsPerInvoke = SetSize)]
    [BenchmarkCategory("random circle-polygon pairs")]
    public float RandomCirclePolygons()
    {
        float sum = 0f;
        for (int i = 0; i < _circles.Length; i++)
        {
            sum += CollisionDetector.Detect(_circles[i], _circlePolygons[i]).MinimumTranslationVector.X;
        }

        return sum;
    }

    /// <summary>The same 1,000 pairs through the frozen kernel.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = SetSize)]
    [BenchmarkCategory("random circle-polygon pairs")]
    public float RandomCirclePolygonsBaseline()
    {
        float sum = 0f;
        for (int i = 0; i < _circles.Length; i++)
        {
            sum += FrozenDetector.Detect(_frozenCircles[i], _frozenCirclePolygons[i]).MinimumTranslationVector.X;
        }

        return sum;
    }

    /// <summary>8-DOP against 8-DOP by the fixed-axis slab test (unchanged kernel, for scale).</summary>
    [Benchmark]
    [BenchmarkCategory("other kinds")]
    public void KDop8KDop8() => _result = CollisionDetector.Detect(_kdopA, _kdopB);

    /// <summary>Axis-aligned box against box (unchanged kernel, for scale).</summary>
    [Benchmark]
    [BenchmarkCategory("other kinds")]
    public void AabbAabb() => _result = CollisionDetector.Detect(_aabbA, _aabbB);

    private static FrozenShapes.ConvexPolygon Frozen(ConvexPolygon polygon) => new(polygon.Vertices);

    private static FrozenShapes.Circle Frozen(Circle circle) => new(circle.Center, circle.Radius);

    /// <summary>
    /// Random convex polygons of 3–8 vertices (points at sorted, jittered angles on a circle of
    /// radius 30–80 mm), in pairs that overlap, or that are separated with overlapping bounding circles.
    /// </summary>
    internal static (ConvexPolygon[] A, ConvexPolygon[] B) RandomPolygonPairs(Random random, bool overlapping)
    {
        var a = new ConvexPolygon[SetSize];
        var b = new ConvexPolygon[SetSize];
        for (int i = 0; i < SetSize;)
        {
            float ra = 30f + (50f * random.NextSingle()), rb = 30f + (50f * random.NextSingle());
            var pa = RandomPolygon(random, Vector2.Zero, ra);
            float distance = (ra + rb) * (overlapping ? 0.3f + (0.6f * random.NextSingle()) : 0.85f + (0.15f * random.NextSingle()));
            float angle = 2f * MathF.PI * random.NextSingle();
            var pb = RandomPolygon(random, distance * new Vector2(MathF.Cos(angle), MathF.Sin(angle)), rb);
            if (CollisionDetector.Detect(pa, pb).Intersect == overlapping)
            {
                a[i] = pa;
                b[i++] = pb;
            }
        }

        return (a, b);
    }

    /// <summary>Random circles (radius 20–70 mm) against random polygons, half of them overlapping.</summary>
    internal static (Circle[] Circles, ConvexPolygon[] Polygons) RandomCirclePolygonPairs(Random random)
    {
        var circles = new Circle[SetSize];
        var polygons = new ConvexPolygon[SetSize];
        for (int i = 0; i < SetSize;)
        {
            float rp = 30f + (50f * random.NextSingle()), rc = 20f + (50f * random.NextSingle());
            var polygon = RandomPolygon(random, Vector2.Zero, rp);
            float distance = (rp + rc) * (0.2f + (0.9f * random.NextSingle()));
            float angle = 2f * MathF.PI * random.NextSingle();
            var circle = new Circle(distance * new Vector2(MathF.Cos(angle), MathF.Sin(angle)), rc);
            if (CollisionDetector.Detect(circle, polygon).Intersect == (i % 2 == 0))
            {
                circles[i] = circle;
                polygons[i++] = polygon;
            }
        }

        return (circles, polygons);
    }

    private static ConvexPolygon RandomPolygon(Random random, Vector2 center, float radius)
    {
        int count = random.Next(3, 9);
        Span<Vector2> points = stackalloc Vector2[count];
        float phase = 2f * MathF.PI * random.NextSingle();
        float step = 2f * MathF.PI / count;
        for (int k = 0; k < count; k++)
        {
            float angle = phase + (k * step) + (0.3f * step * ((2f * random.NextSingle()) - 1f));
            points[k] = center + (radius * new Vector2(MathF.Cos(angle), MathF.Sin(angle)));
        }

        return new ConvexPolygon(points);
    }

    private static Vector2[] Box(Vector2 center, float length, float width, float angle)
    {
        var (s, c) = MathF.SinCos(angle);
        Vector2 u = new(c, s), n = new(-s, c);
        float hl = length / 2f, hw = width / 2f;
        return [center - u * hl - n * hw, center + u * hl - n * hw, center + u * hl + n * hw, center - u * hl + n * hw];
    }

    private static Vector2[] Regular(Vector2 center, float radius, int count, float phase)
    {
        var v = new Vector2[count];
        for (int i = 0; i < count; i++)
        {
            var (s, c) = MathF.SinCos(phase + i * 2f * MathF.PI / count);
            v[i] = center + new Vector2(c, s) * radius;
        }

        return v;
    }
}
