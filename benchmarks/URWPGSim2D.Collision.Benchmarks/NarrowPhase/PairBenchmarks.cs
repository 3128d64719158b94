using System;
using System.Numerics;
using BenchmarkDotNet.Attributes;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Benchmarks.NarrowPhase;

/// <summary>
/// Single-pair narrow-phase costs on overlapping pairs (the expensive path: MTV and action point
/// included). Ratios are read against <see cref="CircleCircle"/> (the baseline) and the textbook
/// SAT measured in the same run.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class PairBenchmarks
{
    private Circle _circleA, _circleB;
    private ConvexPolygon _boxA, _boxB, _octA, _octB, _polygon;
    private KDop8 _kdopA, _kdopB;
    private Aabb _aabbA, _aabbB;
    private Vector2[] _boxArrayA = [], _boxArrayB = [], _octArrayA = [], _octArrayB = [];

    /// <summary>Builds overlapping pairs of every benchmarked kind.</summary>
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
    }

    /// <summary>Baseline: circle against circle.</summary>
    [Benchmark(Baseline = true)]
    public CollisionDetectionResult CircleCircle() => CollisionDetector.Detect(_circleA, _circleB);

    /// <summary>Two rotated boxes (4-gons), full SAT with MTV and action point.</summary>
    [Benchmark]
    public CollisionDetectionResult BoxBox() => CollisionDetector.Detect(_boxA, _boxB);

    /// <summary>The same two boxes through the frozen pre-vectorisation SAT (<see cref="ConvexSatBaseline"/>).</summary>
    [Benchmark]
    public CollisionDetectionResult BoxBoxBaseline() => ConvexSatBaseline.Detect(_boxA.View(), _boxB.View());

    /// <summary>Two regular octagons as general polygons.</summary>
    [Benchmark]
    public CollisionDetectionResult OctagonOctagon() => CollisionDetector.Detect(_octA, _octB);

    /// <summary>The same two octagons through the frozen pre-vectorisation SAT.</summary>
    [Benchmark]
    public CollisionDetectionResult OctagonOctagonBaseline() => ConvexSatBaseline.Detect(_octA.View(), _octB.View());

    /// <summary>Circle against hexagon by Voronoi regions.</summary>
    [Benchmark]
    public CollisionDetectionResult CirclePolygon() => CollisionDetector.Detect(_circleA, _polygon);

    /// <summary>8-DOP against 8-DOP by the fixed-axis slab test.</summary>
    [Benchmark]
    public CollisionDetectionResult KDop8KDop8() => CollisionDetector.Detect(_kdopA, _kdopB);

    /// <summary>Axis-aligned box against box.</summary>
    [Benchmark]
    public CollisionDetectionResult AabbAabb() => CollisionDetector.Detect(_aabbA, _aabbB);

    /// <summary>Textbook allocating SAT on the same two boxes (MTV only, no action point).</summary>
    [Benchmark]
    public bool TextbookBoxBox() => TextbookSat.Test(_boxArrayA, _boxArrayB, out _);

    /// <summary>Textbook allocating SAT on the same two octagons.</summary>
    [Benchmark]
    public bool TextbookOctagonOctagon() => TextbookSat.Test(_octArrayA, _octArrayB, out _);

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
