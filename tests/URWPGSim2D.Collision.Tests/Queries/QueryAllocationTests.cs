namespace URWPGSim2D.Collision.Tests.Queries;

/// <summary>The queries are hot paths: after warm-up, none of them allocates.</summary>
public sealed class QueryAllocationTests
{
    [Fact]
    public void ShapeAndWorldQueriesAllocateNothing()
    {
        var rng = new Random(1);
        var (world, shapes, fish) = QueryWorldTests.RandomWorld(rng, BroadPhaseKind.DynamicAabbTree, 40);
        var other = new FishModel(FishSize.Default, new FishPose(new Vector2(100f, 100f), 1f, 0.3f, -0.2f, 0.1f));
        var rays = new (Vector2 From, Vector2 To)[64];
        for (int i = 0; i < rays.Length; i++)
        {
            rays[i] = (FishTestKit.Point(rng, 1500f), FishTestKit.Point(rng, 1500f));
        }

        float sink = Run(world, shapes, fish, other, rays); // warm-up: JIT, static constructors, buffers
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 5; i++)
        {
            sink += Run(world, shapes, fish, other, rays);
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.True(sink != 0f);
        Assert.Equal(0, allocated);
    }

    private static float Run(QueryWorld world, Shape[] shapes, FishModel?[] fish, FishModel other, (Vector2 From, Vector2 To)[] rays)
    {
        Span<BodyRayHit> hits = stackalloc BodyRayHit[8];
        Span<int> found = stackalloc int[16];
        float sum = 0f;
        for (int i = 0; i < shapes.Length; i++)
        {
            var (from, to) = rays[i % rays.Length];
            if (fish[i] is { } f)
            {
                sum += ShapeQuery.Distance(f, other).Distance + ShapeQuery.RayCast(f, from, to).Fraction
                    + ShapeQuery.Cast(f, to - from, other).Fraction + ShapeQuery.Distance(f, from).Distance;
                continue;
            }

            ref readonly Shape a = ref shapes[i];
            ref readonly Shape b = ref shapes[(i + 1) % shapes.Length];
            sum += ShapeQuery.Distance(a, b).Distance + ShapeQuery.RayCast(a, from, to).Fraction
                + ShapeQuery.Cast(a, to - from, b).Fraction + ShapeQuery.Distance(a, other).Distance
                + ShapeQuery.Cast(a, to - from, other).Fraction + ShapeQuery.Distance(a, from).Distance;
        }

        foreach (var (from, to) in rays)
        {
            sum += world.RayCast(from, to).Result.Fraction + world.RayCastAll(from, to, hits)
                + world.Overlap(new Aabb(Vector2.Min(from, to), Vector2.Max(from, to)), found) + world.Nearest(from).Result.Distance;
        }

        return sum;
    }
}
