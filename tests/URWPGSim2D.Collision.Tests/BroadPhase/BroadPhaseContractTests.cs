namespace URWPGSim2D.Collision.Tests.BroadPhase;

/// <summary>Hand-made cases, the bad-input rule, balance of the tree and zero allocation once warm.</summary>
public sealed class BroadPhaseContractTests
{
    public static TheoryData<string> Kinds() => BroadPhaseEquivalenceTests.Kinds();

    [Theory]
    [MemberData(nameof(Kinds))]
    public void TouchingBoxesOverlapAndStaticPairsAreNeverReported(string kind)
    {
        var bp = BroadPhaseEquivalenceTests.Create(kind);
        Aabb[] boxes =
        [
            Box(0, 0, 10, 10),      // 0 moving
            Box(10, 0, 20, 10),     // 1 moving: touches 0 along x = 10
            Box(20.5f, 0, 30, 10),  // 2 moving: 0.5 mm from 1
            Box(0, 10, 10, 20),     // 3 static: touches 0 along z = 10
            Box(5, 5, 25, 15),      // 4 static: overlaps 0, 1, 2 and static 3
        ];
        bp.Reset(boxes, movingCount: 3);
        var pairs = new PairList();
        bp.FindPairs(pairs);
        Assert.Equal(new[] { P(0, 1), P(0, 3), P(0, 4), P(1, 3), P(1, 4), P(2, 4) }, pairs.Items.ToArray());

        var found = new IndexList();
        bp.Query(Box(10, 10, 10, 10), found); // a point shared by 0, 1, 3 and 4
        Assert.Equal(new[] { 0, 1, 3, 4 }, found.Items.ToArray());

        bp.Move(2, Box(100, 100, 110, 110));
        bp.FindPairs(pairs);
        Assert.Equal(new[] { P(0, 1), P(0, 3), P(0, 4), P(1, 3), P(1, 4) }, pairs.Items.ToArray());
        Assert.Equal(Box(100, 100, 110, 110).Max, bp.Box(2).Max);
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void BadArgumentsNameTheParameterAndTheValue(string kind)
    {
        var bp = BroadPhaseEquivalenceTests.Create(kind);
        Aabb[] boxes = [Box(0, 0, 1, 1), Box(2, 2, 3, 3)];
        ArgumentAssert.Throws("movingCount", () => bp.Reset(boxes, 3), "0 … 2", "got 3");
        ArgumentAssert.Throws("movingCount", () => bp.Reset(boxes, -1), "got -1");
        bp.Reset(boxes, 2);
        ArgumentAssert.Throws("proxy", () => bp.Move(2, boxes[0]), "0 … 1", "got 2");
        ArgumentAssert.Throws("proxy", () => bp.Box(-1), "got -1");
    }

    [Fact]
    public void ConstructorsRejectBadParameters()
    {
        ArgumentAssert.Throws("cellSize", () => new UniformGrid(cellSize: -1f), "got -1");
        ArgumentAssert.Throws("cellSize", () => new UniformGrid(cellSize: float.NaN), "got NaN");
        ArgumentAssert.Throws("cellScale", () => new UniformGrid(cellScale: 0.5f), "≥ 1", "got 0.5");
        ArgumentAssert.Throws("marginScale", () => new DynamicAabbTree(marginScale: -0.5f), "got -0.5");
        ArgumentAssert.Throws("capacity", () => new PairList(-1), "got -1");
        ArgumentAssert.Throws("capacity", () => new IndexList(-2), "got -2");
    }

    [Fact]
    public void TheGridChoosesItsCellFromTheMovingBoxes()
    {
        var grid = new UniformGrid(cellScale: 2f);
        grid.Reset([Box(0, 0, 100, 40), Box(0, 0, 300, 300), Box(0, 0, 5000, 5000)], movingCount: 2);
        Assert.Equal(600f / 0.995f, grid.CellSize, 1e-3f); // 2 × the larger moving extent (300), +0.5 %; the static box is ignored
        var fixedGrid = new UniformGrid(cellSize: 250f);
        fixedGrid.Reset([Box(0, 0, 1, 1)], 1);
        Assert.Equal(250f, fixedGrid.CellSize);
    }

    [Fact]
    public void TheTreeStaysBalancedWhileProxiesMove()
    {
        var tree = new DynamicAabbTree();
        var world = new RandomBoxWorld(seed: 77);
        Aabb[] boxes = world.Boxes(2048, 20_000f);
        tree.Reset(boxes, boxes.Length);
        Assert.InRange(tree.Height, 11, 2 * 11);
        for (int i = 0; i < 20_000; i++)
        {
            int p = world.Random.Next(boxes.Length);
            tree.Move(p, world.Box(20_000f));
        }

        Assert.InRange(tree.Height, 11, 2 * 11);
    }

    // A measured stretch is repeated up to three times: a cycle of the code's own that allocates
    // does so every time, a one-off allocation of the runtime's (a method's code replaced by its
    // optimised version while the stretch runs) only in the one it falls in.
    private const int Windows = 3;

    [Theory]
    [MemberData(nameof(Kinds))]
    public void FindingPairsAllocatesNothingOnceWarm(string kind) => AllocatesNothingOnceWarm(kind, 500, 3000f, 100);

    [Fact]
    public void FindingPairsInASmallWorldAllocatesNothingOnceWarm() => AllocatesNothingOnceWarm("grid", 40, 300f, 20);

    private static void AllocatesNothingOnceWarm(string kind, int count, float half, int leastPairs)
    {
        var bp = BroadPhaseEquivalenceTests.Create(kind);
        var world = new RandomBoxWorld(seed: 3);
        Aabb[] boxes = world.Boxes(count, half);
        int movingCount = count * 4 / 5;
        var pairs = new PairList();
        var found = new IndexList();
        // Warm: one whole round of what is measured, Move included (its first call may size its buffers).
        bp.Reset(boxes, movingCount);
        bp.FindPairs(pairs);
        bp.Move(7, boxes[8]);
        bp.Query(boxes[0], found);
        var windows = new long[Windows];
        for (int w = 0; w < Windows; w++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int round = 0; round < 5; round++)
            {
                bp.Reset(boxes, movingCount);
                bp.FindPairs(pairs);
                bp.Move(7, boxes[8]);
                bp.Query(boxes[0], found);
            }

            windows[w] = GC.GetAllocatedBytesForCurrentThread() - before;
            if (windows[w] == 0L)
            {
                break;
            }
        }

        Assert.True(windows.Contains(0L), $"{kind}: {string.Join(", ", windows)} B in {Windows} windows of 5 rounds");
        Assert.True(pairs.Count > leastPairs, $"{kind}: only {pairs.Count} pairs");
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void BodiesSpreadingOutAllocateNothing(string kind)
    {
        // Warm on boxes crowded into a corner, then as many spread over the whole field: a layout
        // sized to where the bodies were would have to grow for where they went. Each window starts
        // from a new broad phase, so a buffer that grows does so in every window.
        var world = new RandomBoxWorld(seed: 4);
        Aabb[] crowded = world.Boxes(300, 200f);
        Aabb[] spread = world.Boxes(300, 6000f);
        var pairs = new PairList();
        var windows = new long[Windows];
        for (int w = 0; w < Windows; w++)
        {
            var bp = BroadPhaseEquivalenceTests.Create(kind);
            bp.Reset(crowded, 300);
            bp.FindPairs(pairs);
            bp.Reset(crowded, 300);
            bp.FindPairs(pairs);
            long before = GC.GetAllocatedBytesForCurrentThread();
            bp.Reset(spread, 300);
            bp.FindPairs(pairs);
            windows[w] = GC.GetAllocatedBytesForCurrentThread() - before;
            if (windows[w] == 0L)
            {
                break;
            }
        }

        Assert.True(windows.Contains(0L), $"{kind}: {string.Join(", ", windows)} B in {Windows} windows");
    }

    private static Aabb Box(float x0, float z0, float x1, float z1) => new(new Vector2(x0, z0), new Vector2(x1, z1));

    private static ProxyPair P(int a, int b) => new(a, b);
}
