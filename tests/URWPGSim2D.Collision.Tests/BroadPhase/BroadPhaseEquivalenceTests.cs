namespace URWPGSim2D.Collision.Tests.BroadPhase;

/// <summary>
/// Every broad phase reports exactly the pairs brute force finds (every pair of boxes tested), in
/// the same order, over many random worlds: after a reset, after many moves, and for queries.
/// </summary>
public sealed class BroadPhaseEquivalenceTests
{
    private const int Worlds = 150;

    public static TheoryData<string> Kinds() => new() { "grid", "grid-fine", "grid-coarse", "grid-tiny", "sap", "tree" };

    internal static IBroadPhase Create(string kind) => kind switch
    {
        "grid" => new UniformGrid(),
        "grid-fine" => new UniformGrid(cellSize: 40f),
        "grid-coarse" => new UniformGrid(cellScale: 6f),
        "grid-tiny" => new UniformGrid(cellSize: 0.5f),
        "sap" => new SweepAndPrune(),
        "tree" => new DynamicAabbTree(),
        _ => throw new ArgumentException(kind),
    };

    [Theory]
    [MemberData(nameof(Kinds))]
    public void FindsExactlyThePairsBruteForceFindsOverManyRandomWorlds(string kind)
    {
        var truth = new BruteForceBroadPhase();
        var tested = Create(kind);
        var expected = new PairList();
        var actual = new PairList();
        int pairsSeen = 0;
        for (int w = 0; w < Worlds; w++)
        {
            var world = new RandomBoxWorld(seed: 7000 + w);
            int n = world.Random.Next(w % 10 == 0 ? 4 : 260);
            float half = world.Random.Next(3) switch { 0 => 300f, 1 => 2000f, _ => 8000f };
            Aabb[] boxes = world.Boxes(n, half);
            int moving = n == 0 ? 0 : world.Random.Next(n + 1);
            truth.Reset(boxes, moving);
            tested.Reset(boxes, moving);
            Compare(truth, tested, expected, actual, $"{kind} world {w} after reset");
            pairsSeen += expected.Count;

            for (int round = 0; round < 4; round++)
            {
                for (int m = 0; m < n / 3; m++)
                {
                    int p = world.Random.Next(n);
                    Aabb moved = world.Moved(truth.Box(p), half);
                    truth.Move(p, moved);
                    tested.Move(p, moved);
                }

                Compare(truth, tested, expected, actual, $"{kind} world {w} after moves {round}");
                pairsSeen += expected.Count;
            }

            // The same count again: implementations may update in place instead of rebuilding.
            for (int i = 0; i < n; i++)
            {
                boxes[i] = world.Moved(boxes[i], half);
            }

            truth.Reset(boxes, moving);
            tested.Reset(boxes, moving);
            Compare(truth, tested, expected, actual, $"{kind} world {w} after a second reset");
        }

        Assert.True(pairsSeen > 20_000, $"only {pairsSeen} pairs were compared");
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void QueriesFindExactlyTheProxiesBruteForceFinds(string kind)
    {
        var truth = new BruteForceBroadPhase();
        var tested = Create(kind);
        var expected = new IndexList();
        var actual = new IndexList();
        int found = 0;
        for (int w = 0; w < 40; w++)
        {
            var world = new RandomBoxWorld(seed: 9100 + w);
            int n = world.Random.Next(300);
            float half = w % 2 == 0 ? 1000f : 6000f;
            Aabb[] boxes = world.Boxes(n, half);
            truth.Reset(boxes, n / 2);
            tested.Reset(boxes, n / 2);
            for (int q = 0; q < 60; q++)
            {
                if (n > 0 && q % 3 == 0)
                {
                    int p = world.Random.Next(n);
                    Aabb moved = world.Moved(truth.Box(p), half);
                    truth.Move(p, moved);
                    tested.Move(p, moved);
                }

                Aabb box = q % 7 == 0 ? new Aabb(new(-half * 2f), new(half * 2f)) : world.Box(half);
                truth.Query(box, expected);
                tested.Query(box, actual);
                Assert.True(expected.Items.SequenceEqual(actual.Items), $"{kind} world {w} query {q}: expected [{string.Join(",", expected.Items.ToArray())}] got [{string.Join(",", actual.Items.ToArray())}]");
                found += expected.Count;
            }
        }

        Assert.True(found > 5_000, $"only {found} proxies were found");
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(40f)]
    public void OneGridSwitchingBetweenSmallAndLargeWorldsFindsWhatBruteForceFinds(float cellSize)
    {
        // A grid of at most 48 proxies tests every two and lays out no cells; one instance goes
        // back and forth across that size, with moves in between, pairs and queries checked each time.
        var truth = new BruteForceBroadPhase();
        var grid = new UniformGrid(cellSize);
        var expected = new PairList();
        var actual = new PairList();
        var expectedNear = new IndexList();
        var actualNear = new IndexList();
        var world = new RandomBoxWorld(seed: 4848);
        int pairs = 0;
        foreach (int n in new[] { 48, 49, 10, 200, 47, 0, 48, 120, 3, 49, 48, 60 })
        {
            float half = n > 48 ? 1500f : 400f;
            Aabb[] boxes = world.Boxes(n, half);
            int moving = n - (n / 4);
            truth.Reset(boxes, moving);
            grid.Reset(boxes, moving);
            for (int round = 0; round < 3; round++)
            {
                Compare(truth, grid, expected, actual, $"{n} boxes, round {round}");
                pairs += expected.Count;
                for (int m = 0; m < n / 2; m++)
                {
                    int p = world.Random.Next(n);
                    Aabb moved = world.Moved(truth.Box(p), half);
                    truth.Move(p, moved);
                    grid.Move(p, moved);
                }

                Aabb query = world.Box(half);
                truth.Query(query, expectedNear);
                grid.Query(query, actualNear);
                Assert.True(expectedNear.Items.SequenceEqual(actualNear.Items), $"{n} boxes, query {round}");
            }

            if (n <= 48)
            {
                Assert.Equal(0, grid.OversizeCount); // none is left from the large world before
            }
        }

        Assert.True(pairs > 1000, $"only {pairs} pairs were compared");
    }

    [Fact]
    public void TheBruteForceReferenceIsTheDefinition()
    {
        // Independent of any broad phase code: the definition of the answer, pair by pair.
        var world = new RandomBoxWorld(seed: 5);
        Aabb[] boxes = world.Boxes(120, 800f);
        var brute = new BruteForceBroadPhase();
        brute.Reset(boxes, 90);
        var pairs = new PairList();
        brute.FindPairs(pairs);
        var expected = new List<ProxyPair>();
        for (int a = 0; a < boxes.Length; a++)
        {
            for (int b = a + 1; b < boxes.Length; b++)
            {
                bool overlap = boxes[a].Min.X <= boxes[b].Max.X && boxes[b].Min.X <= boxes[a].Max.X
                    && boxes[a].Min.Y <= boxes[b].Max.Y && boxes[b].Min.Y <= boxes[a].Max.Y;
                if (overlap && (a < 90 || b < 90))
                {
                    expected.Add(new ProxyPair(a, b));
                }
            }
        }

        Assert.Equal(expected, pairs.Items.ToArray());
        Assert.True(expected.Count > 50);
    }

    private static void Compare(IBroadPhase truth, IBroadPhase tested, PairList expected, PairList actual, string where)
    {
        truth.FindPairs(expected);
        tested.FindPairs(actual);
        if (expected.Items.SequenceEqual(actual.Items))
        {
            return;
        }

        var missing = expected.Items.ToArray().Except(actual.Items.ToArray()).Take(5);
        var extra = actual.Items.ToArray().Except(expected.Items.ToArray()).Take(5);
        Assert.Fail($"{where}: {expected.Count} expected, {actual.Count} found; missing {string.Join(" ", missing)}; extra {string.Join(" ", extra)}");
    }
}
