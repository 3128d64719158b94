namespace URWPGSim2D.Collision.Tests.Queries;

/// <summary>
/// <see cref="QueryWorld"/> through every broad phase gives the answers of brute force: every
/// body asked with <see cref="ShapeQuery"/> and <see cref="CollisionDetector"/> one by one.
/// </summary>
public sealed class QueryWorldTests
{
    public static TheoryData<BroadPhaseKind> BroadPhases => [.. Enum.GetValues<BroadPhaseKind>()];

    [Theory]
    [MemberData(nameof(BroadPhases))]
    public void RayCastsOverlapsAndNearestAreThoseOfBruteForce(BroadPhaseKind kind)
    {
        var rng = new Random(4242);
        var (world, shapes, fish) = RandomWorld(rng, kind, 60);
        var hits = new BodyRayHit[8];
        var found = new int[64];
        int rayHits = 0, overlaps = 0;
        for (int q = 0; q < 300; q++)
        {
            Vector2 from = FishTestKit.Point(rng, 1500f), to = FishTestKit.Point(rng, 1500f);
            var expected = Enumerable.Range(0, world.Count)
                .Select(b => (Body: b, Hit: fish[b] is { } f ? ShapeQuery.RayCast(f, from, to) : ShapeQuery.RayCast(shapes[b], from, to)))
                .Where(x => x.Hit.Hit)
                .OrderBy(x => x.Hit.Fraction).ThenBy(x => x.Body)
                .ToArray();
            var closest = world.RayCast(from, to);
            Assert.Equal(expected.Length == 0 ? -1 : expected[0].Body, closest.Body);
            if (expected.Length > 0)
            {
                rayHits++;
                Assert.Equal(expected[0].Hit.Fraction, closest.Result.Fraction);
            }

            int n = world.RayCastAll(from, to, hits);
            Assert.Equal(expected.Length, n);
            Assert.Equal(expected.Take(hits.Length).Select(x => x.Hit.Fraction), hits.Take(Math.Min(n, hits.Length)).Select(h => h.Result.Fraction));

            Vector2 c = FishTestKit.Point(rng, 1500f), h = new(FishTestKit.Range(rng, 1f, 400f), FishTestKit.Range(rng, 1f, 400f));
            var box = new Aabb(c - h, c + h);
            var inBox = Enumerable.Range(0, world.Count)
                .Where(b => fish[b] is { } f ? FishCollision.Detect(f, (Shape)box).Intersect : CollisionDetector.Detect(shapes[b], box).Intersect)
                .ToArray();
            int m = world.Overlap(box, found);
            Assert.Equal(inBox, found.Take(m));
            overlaps += m;

            Vector2 p = FishTestKit.Point(rng, 2500f);
            var nearest = Enumerable.Range(0, world.Count)
                .Select(b => (Body: b, D: fish[b] is { } f ? ShapeQuery.Distance(f, p).Distance : ShapeQuery.Distance(shapes[b], p).Distance))
                .OrderBy(x => x.D).ThenBy(x => x.Body).First();
            var got = world.Nearest(p);
            Assert.Equal(nearest.D, got.Result.Distance);
        }

        Assert.True(rayHits > 100 && overlaps > 100, $"too few hits ({rayHits}) or overlaps ({overlaps})");
    }

    [Fact]
    public void MovingAFishAndReplacingAShapeAreSeen()
    {
        var world = new QueryWorld(BroadPhaseKind.UniformGrid);
        var fish = new FishModel(FishSize.Default, new FishPose(new Vector2(0f, 0f), 0f));
        int f = world.Add(fish);
        int c = world.Add(new Circle(new Vector2(1000f, 0f), 50f));
        Assert.Equal(f, world.RayCast(new Vector2(-500f, 0f), new Vector2(2000f, 0f)).Body);

        fish.SetPose(new FishPose(new Vector2(0f, 3000f), 0f));
        world.Refresh(f);
        Assert.Equal(c, world.RayCast(new Vector2(-500f, 0f), new Vector2(2000f, 0f)).Body);

        world.Update(c, new Circle(new Vector2(1000f, 500f), 50f));
        Assert.Equal(-1, world.RayCast(new Vector2(-500f, 0f), new Vector2(2000f, 0f)).Body);
        Assert.Equal(c, world.Nearest(new Vector2(1000f, 400f)).Body);
        Assert.Throws<ArgumentException>(() => world.Refresh(2));
        world.Clear();
        Assert.Equal(-1, world.Nearest(Vector2.Zero).Body);
    }

    internal static (QueryWorld World, Shape[] Shapes, FishModel?[] Fish) RandomWorld(Random rng, BroadPhaseKind kind, int count)
    {
        var world = new QueryWorld(kind);
        var shapes = new Shape[count];
        var fish = new FishModel?[count];
        for (int i = 0; i < count; i++)
        {
            if (i % 10 == 3)
            {
                fish[i] = new FishModel(FishTestKit.Size(rng), FishTestKit.Pose(rng, spread: 1500f));
                world.Add(fish[i]!);
                continue;
            }

            shapes[i] = (i % 5) switch
            {
                0 => FishTestKit.Circle(rng, 1500f),
                1 => FishTestKit.Aabb(rng, 1500f),
                2 => FishTestKit.KDop(rng, 1500f),
                3 => FishTestKit.Polygon(rng, 1500f),
                _ => new Segment(FishTestKit.Point(rng, 1500f), FishTestKit.Point(rng, 1500f)),
            };
            world.Add(shapes[i]);
        }

        return (world, shapes, fish);
    }
}
