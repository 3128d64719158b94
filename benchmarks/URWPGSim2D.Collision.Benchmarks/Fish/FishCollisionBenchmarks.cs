using System;
using System.Numerics;
using BenchmarkDotNet.Attributes;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Benchmarks.NarrowPhase;
using URWPGSim2D.Collision.NarrowPhase;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Benchmarks.Fish;

/// <summary>
/// Costs of the fish tree against the narrow-phase primitives, in one class so that the ratios
/// come from the same run: a circle–circle test that misses (the baseline; like the fish queries
/// it returns the full result struct), one leaf-vs-leaf SAT, and the fish queries and pose updates. Run: <c>dotnet run -c Release --project benchmarks/URWPGSim2D.Collision.Benchmarks -- --filter *FishCollision* --job short</c>.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class FishCollisionBenchmarks
{
    private readonly FishPose[] _poses = new FishPose[16];
    private readonly FishPose[] _swim = new FishPose[64];
    private FishModel _fish = null!;
    private FishModel _nearMiss = null!;
    private FishModel _crossing = null!;
    private FishModel _updated = null!;
    private Circle _ballA;
    private Circle _ballApart;
    private Circle _ballOverlapping;
    private Circle _ballFar;
    private Circle _ballAtTail;
    private int _next;

    [GlobalSetup]
    public void Setup()
    {
        // A swimming fish at the origin, tail bent a little.
        _fish = new FishModel(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0.25f, 0.1f, -0.2f));

        // Parallel neighbour 10 mm beside the pectoral fins: every circle overlaps, no leaf does.
        _nearMiss = new FishModel(FishSize.Default, new FishPose(new Vector2(-30f, 131f), 0f, -0.05f, -0.1f, 0.05f));

        // A fish crossing the first one's body at right angles: several leaf pairs overlap.
        _crossing = new FishModel(FishSize.Default, new FishPose(new Vector2(10f, -40f), MathF.PI / 2f, 0.3f, 0.2f, -0.1f));
        _updated = new FishModel(FishSize.Default, default);

        _ballA = new Circle(new Vector2(0f, 0f), 58f);
        _ballApart = new Circle(new Vector2(300f, 40f), 58f);
        _ballOverlapping = new Circle(new Vector2(80f, 20f), 58f);
        _ballFar = new Circle(new Vector2(500f, 300f), 58f);
        _ballAtTail = new Circle(new Vector2(-300f, 70f), 58f);
        var rng = new Random(7);
        for (int i = 0; i < _poses.Length; i++)
        {
            _poses[i] = new FishPose(new Vector2(rng.Next(-1400, 1400), rng.Next(-900, 900)), (float)(rng.NextDouble() * 6.28), (float)(rng.NextDouble() - 0.5), (float)(rng.NextDouble() - 0.5), (float)(rng.NextDouble() - 0.5));
        }

        // One cycle (100 ms) after another: 200 mm/s, turning, tail wave at 1 Hz.
        for (int i = 0; i < _swim.Length; i++)
        {
            float t = 0.1f * i, heading = 0.05f * i;
            Vector2 p = new(20f * i * MathF.Cos(0.5f * heading), 20f * i * MathF.Sin(0.5f * heading));
            float w = 2f * MathF.PI * t;
            _swim[i] = new FishPose(p, heading, 0.25f * MathF.Sin(w), 0.3f * MathF.Sin(w + 1.4f), 0.35f * MathF.Sin(w + 2.4f));
        }

        Console.WriteLine($"// near miss contacts: {FishCollision.DetectAll(_fish, _nearMiss, new FishContact[64])}, candidate leaf pairs: {CandidatePairs(_fish, _nearMiss)}");
        Console.WriteLine($"// crossing contacts: {FishCollision.DetectAll(_fish, _crossing, new FishContact[64])}, candidate leaf pairs: {CandidatePairs(_fish, _crossing)}");
        Console.WriteLine($"// ball at tail hits: {FishCollision.Detect(_fish, _ballAtTail)}, far ball root overlap: {_fish.Root.Overlaps(_ballFar)}");
    }

    [Benchmark(Baseline = true)]
    public CollisionDetectionResult CircleCircleMiss() => CollisionDetector.Detect(_ballA, _ballApart);

    [Benchmark]
    public CollisionDetectionResult CircleCircleHit() => CollisionDetector.Detect(_ballA, _ballOverlapping);

    [Benchmark]
    public CollisionDetectionResult LeafVsLeafSat() => ConvexSat.Detect(_fish.LeafView((int)FishPart.Body), _crossing.LeafView((int)FishPart.Body));

    [Benchmark]
    public CollisionDetectionResult LeafVsLeafSatBaseline() => ConvexSatBaseline.Detect(_fish.LeafView((int)FishPart.Body), _crossing.LeafView((int)FishPart.Body));

    [Benchmark]
    public FishContact FishVsBallRootMiss() => FishCollision.Detect(_fish, _ballFar);

    [Benchmark]
    public FishContact FishVsBallLeafHit() => FishCollision.Detect(_fish, _ballAtTail);

    [Benchmark]
    public FishContact FishVsFishNearMiss() => FishCollision.Detect(_fish, _nearMiss);

    [Benchmark]
    public FishContact FishVsFishDeepOverlap() => FishCollision.Detect(_fish, _crossing);

    [Benchmark]
    public Circle PoseUpdateRandom()
    {
        _updated.SetPose(_poses[_next++ & 15]);
        return _updated.Root;
    }

    [Benchmark]
    public Circle PoseUpdateSwimming()
    {
        _updated.SetPose(_swim[_next++ & 63]);
        return _updated.Root;
    }

    // Leaf pairs that reach the exact test: group circles and both leaf 8-DOPs overlap.
    private static int CandidatePairs(FishModel a, FishModel b)
    {
        int count = 0;
        for (int la = 0; la < 8; la++)
        {
            for (int lb = 0; lb < 8; lb++)
            {
                Circle ga = la < 3 ? a.BodyGroup : a.TailGroup, gb = lb < 3 ? b.BodyGroup : b.TailGroup;
                count += ga.Overlaps(gb) && a.GetLeafBound((FishPart)la).Overlaps(b.GetLeafBound((FishPart)lb)) ? 1 : 0;
            }
        }

        return count;
    }
}
