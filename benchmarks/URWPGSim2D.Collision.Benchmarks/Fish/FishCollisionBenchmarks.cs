extern alias baseline;

using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.NarrowPhase;
using URWPGSim2D.Collision.Shapes;
using FrozenFish = baseline::URWPGSim2D.Collision.Fish;
using FrozenResult = baseline::URWPGSim2D.Collision.CollisionDetectionResult;
using FrozenSat = baseline::URWPGSim2D.Collision.NarrowPhase.ConvexSat;
using FrozenShapes = baseline::URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Benchmarks.Fish;

/// <summary>
/// Costs of the fish tree against the narrow-phase primitives, in one class so that the ratios
/// come from the same run: a circle–circle test that misses (the baseline; like the fish queries
/// it returns the full result struct), one leaf-vs-leaf SAT, and the fish queries and pose updates;
/// the <c>…Baseline</c> rows are the same work in the frozen baseline (the library of the commit
/// tagged <c>benchmark-baseline</c>, under the extern alias <c>baseline</c>) on the same poses. Run: <c>dotnet run -c Release --project benchmarks/URWPGSim2D.Collision.Benchmarks -- --filter *FishCollision* --job short</c>.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class FishCollisionBenchmarks
{
    // What each benchmark computes is kept here (a void benchmark's result must stay alive, and
    // BenchmarkDotNet's generated project cannot name a type that the library and the frozen
    // baseline both define).
    private FishContact _contact;
    private FrozenFish.FishContact _frozenContact;
    private FrozenResult _frozenResult;
    private FrozenShapes.Circle _frozenRoot;
    private CollisionDetectionResult _result;
    private Circle _root;

    private readonly FishPose[] _poses = new FishPose[16];
    private readonly FishPose[] _swim = new FishPose[64];
    private readonly FishPose[] _bracket = new FishPose[64];
    private FishModel _fish = null!;
    private FishModel _nearMiss = null!;
    private FishModel _crossing = null!;
    private FishModel _updated = null!;
    private FrozenFish.FishModel _frozenFish = null!;
    private FrozenFish.FishModel _frozenCrossing = null!;
    private FrozenFish.FishModel _frozenUpdated = null!;
    private readonly FrozenFish.FishPose[] _frozenPoses = new FrozenFish.FishPose[16];
    private readonly FrozenFish.FishPose[] _frozenSwim = new FrozenFish.FishPose[64];
    private readonly FrozenFish.FishPose[] _frozenBracket = new FrozenFish.FishPose[64];
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

        // Within one cycle: the tail pose is fixed while sub-steps and the search for the time of
        // first contact move the fish back and forth along its path (position and heading only).
        for (int i = 0; i < _bracket.Length; i++)
        {
            float s = (i * 37 % 64) / 64f;
            _bracket[i] = new FishPose(new Vector2(300f + 20f * s, -200f + 5f * s), 0.7f + 0.05f * s, 0.21f, -0.13f, 0.33f);
        }

        // The same fish and poses in the frozen baseline.
        _frozenFish = new FrozenFish.FishModel(FrozenFish.FishSize.Default, Frozen(_fish.Pose));
        _frozenCrossing = new FrozenFish.FishModel(FrozenFish.FishSize.Default, Frozen(_crossing.Pose));
        _frozenUpdated = new FrozenFish.FishModel(FrozenFish.FishSize.Default, default);
        for (int i = 0; i < _poses.Length; i++)
        {
            _frozenPoses[i] = Frozen(_poses[i]);
        }

        for (int i = 0; i < _swim.Length; i++)
        {
            (_frozenSwim[i], _frozenBracket[i]) = (Frozen(_swim[i]), Frozen(_bracket[i]));
        }

        Console.WriteLine($"// near miss contacts: {FishCollision.DetectAll(_fish, _nearMiss, new FishContact[64])}, candidate leaf pairs: {CandidatePairs(_fish, _nearMiss)}");
        Console.WriteLine($"// crossing contacts: {FishCollision.DetectAll(_fish, _crossing, new FishContact[64])}, candidate leaf pairs: {CandidatePairs(_fish, _crossing)}");
        var deep = FishCollision.Detect(_fish, _crossing);
        var frozenDeep = FrozenFish.FishCollision.Detect(_frozenFish, _frozenCrossing);
        Console.WriteLine($"// deep overlap, today = baseline: {deep.Result.MinimumTranslationVector == frozenDeep.Result.MinimumTranslationVector && (int?)deep.PartA == (int?)frozenDeep.PartA && (int?)deep.PartB == (int?)frozenDeep.PartB}");
        Console.WriteLine($"// ball at tail hits: {FishCollision.Detect(_fish, _ballAtTail)}, far ball root overlap: {_fish.Root.Overlaps(_ballFar)}");
    }

    [Benchmark(Baseline = true)]
    public void CircleCircleMiss() => _result = CollisionDetector.Detect(_ballA, _ballApart);

    [Benchmark]
    public void CircleCircleHit() => _result = CollisionDetector.Detect(_ballA, _ballOverlapping);

    [Benchmark]
    public void LeafVsLeafSat() => _result = ConvexSat.Detect(_fish.LeafView((int)FishPart.Body), _crossing.LeafView((int)FishPart.Body));

    [Benchmark]
    public void LeafVsLeafSatBaseline() => _frozenResult = FrozenSat.Detect(_frozenFish.LeafView((int)FrozenFish.FishPart.Body), _frozenCrossing.LeafView((int)FrozenFish.FishPart.Body));

    [Benchmark]
    public void FishVsBallRootMiss() => _contact = FishCollision.Detect(_fish, _ballFar);

    [Benchmark]
    public void FishVsBallLeafHit() => _contact = FishCollision.Detect(_fish, _ballAtTail);

    [Benchmark]
    public void FishVsFishNearMiss() => _contact = FishCollision.Detect(_fish, _nearMiss);

    [Benchmark]
    public void FishVsFishDeepOverlap() => _contact = FishCollision.Detect(_fish, _crossing);

    [Benchmark]
    public void PoseUpdateRandom()
    {
        _updated.SetPose(_poses[_next++ & 15]);
        _root = _updated.Root;
    }

    [Benchmark]
    public void PoseUpdateSwimming()
    {
        _updated.SetPose(_swim[_next++ & 63]);
        _root = _updated.Root;
    }

    [Benchmark]
    public void PoseUpdateSameJoints()
    {
        _updated.SetPose(_bracket[_next++ & 63]);
        _root = _updated.Root;
    }

    [Benchmark]
    public void PoseUpdateSameJointsBaseline()
    {
        _frozenUpdated.SetPose(_frozenBracket[_next++ & 63]);
        _frozenRoot = _frozenUpdated.Root;
    }

    [Benchmark]
    public void PoseUpdateRandomBaseline()
    {
        _frozenUpdated.SetPose(_frozenPoses[_next++ & 15]);
        _frozenRoot = _frozenUpdated.Root;
    }

    [Benchmark]
    public void PoseUpdateSwimmingBaseline()
    {
        _frozenUpdated.SetPose(_frozenSwim[_next++ & 63]);
        _frozenRoot = _frozenUpdated.Root;
    }

    /// <summary>The deepest fish–fish contact in the frozen baseline.</summary>
    [Benchmark]
    public void FishVsFishDeepOverlapBaseline() => _frozenContact = FrozenFish.FishCollision.Detect(_frozenFish, _frozenCrossing);

    private static FrozenFish.FishPose Frozen(in FishPose p) => new(p.Position, p.Heading, p.Joint1, p.Joint2, p.Joint3);

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
