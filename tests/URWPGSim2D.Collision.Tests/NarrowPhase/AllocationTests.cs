namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>The narrow phase is a hot path: after warm-up, <c>Detect</c> allocates nothing, whatever the pair or outcome.</summary>
public sealed class AllocationTests
{
    private const int Repeats = 20;

    [Fact]
    public void DetectAllocatesNothingForAnyPairOrOutcome()
    {
        // 40 cases per ordered pair: overlapping, contained, grazing (fallback paths) and apart.
        var shapes = Enum.GetValues<ShapeKind>()
            .SelectMany(a => Enum.GetValues<ShapeKind>(), (a, b) => PairCorpus.For(a, b).Take(40))
            .SelectMany(c => c)
            .Select(c => (c.A.Shape, c.B.Shape))
            .ToArray();
        Assert.Equal(25 * 40, shapes.Length);

        int hits = RunAll(shapes); // warm-up: JIT, static constructors
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < Repeats; i++)
        {
            hits += RunAll(shapes);
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.True(hits > shapes.Length, "the cases should include contacts");
        Assert.Equal(0, allocated);
    }

    private static int RunAll((Shape A, Shape B)[] pairs)
    {
        int hits = 0;
        foreach (var (a, b) in pairs)
        {
            // Both the run-time dispatch and the typed overloads, in both orders.
            hits += CollisionDetector.Detect(a, b).Intersect ? 1 : 0;
            hits += TypedDetect.Detect(b, a).Intersect ? 1 : 0;
        }

        return hits;
    }
}
