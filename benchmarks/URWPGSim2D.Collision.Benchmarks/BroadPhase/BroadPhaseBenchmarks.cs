namespace URWPGSim2D.Collision.Benchmarks.BroadPhase;

/// <summary>
/// One cycle of broad phase for n moving objects at the default match's density
/// (<see cref="MovingBoxWorld"/>): every box gets its new position (<see cref="IBroadPhase.Reset"/>:
/// a rebuild for the grid, insertion-sort repair for sweep and prune, re-insertion of the leaves
/// that left their fat box for the tree), then every overlapping pair is listed, sorted. Brute
/// force (n·(n − 1)/2 box tests) is the baseline.
/// </summary>
[MemoryDiagnoser]
public class BroadPhaseBenchmarks
{
    private MovingBoxWorld _world = null!;
    private readonly PairList _pairs = new();
    private BruteForceBroadPhase _brute = null!;
    private UniformGrid _grid = null!;
    private SweepAndPrune _sap = null!;
    private DynamicAabbTree _tree = null!;
    private int _step;

    /// <summary>Number of moving objects.</summary>
    [Params(100, 1_000, 10_000)]
    public int Objects { get; set; }

    /// <summary>Builds the frames and warms every broad phase on them.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new MovingBoxWorld(Objects);
        _brute = new BruteForceBroadPhase();
        _grid = new UniformGrid();
        _sap = new SweepAndPrune();
        _tree = new DynamicAabbTree();
        foreach (IBroadPhase bp in new IBroadPhase[] { _grid, _sap, _tree })
        {
            for (int f = 0; f < MovingBoxWorld.Frames; f++)
            {
                Cycle(bp);
            }
        }
    }

    /// <summary>Every pair tested.</summary>
    [Benchmark(Baseline = true)]
    public int BruteForce() => Cycle(_brute);

    /// <summary>Uniform grid, cell = the largest box extent.</summary>
    [Benchmark]
    public int Grid() => Cycle(_grid);

    /// <summary>Sweep and prune on x.</summary>
    [Benchmark]
    public int SweepAndPrune() => Cycle(_sap);

    /// <summary>Dynamic AABB tree.</summary>
    [Benchmark]
    public int DynamicTree() => Cycle(_tree);

    private int Cycle(IBroadPhase bp)
    {
        // Back and forth through the frames, so that consecutive cycles are always consecutive frames.
        _step = (_step + 1) % (2 * (MovingBoxWorld.Frames - 1));
        int frame = _step < MovingBoxWorld.Frames ? _step : (2 * (MovingBoxWorld.Frames - 1)) - _step;
        bp.Reset(_world.Boxes[frame], _world.Count);
        bp.FindPairs(_pairs);
        return _pairs.Count;
    }
}
