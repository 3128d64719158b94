namespace URWPGSim2D.Collision.Tests.Fish;

public class FishAllocationTests
{
    [Fact]
    public void PoseUpdateAllocatesNothing()
    {
        var fish = new FishModel(FishSize.Default, default);
        var poses = new FishPose[64];
        var rng = new Random(41);
        for (int i = 0; i < poses.Length; i++)
        {
            poses[i] = FishTestKit.Pose(rng);
        }

        Run(() =>
        {
            foreach (var p in poses)
            {
                fish.SetPose(p);
            }
        });
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int round = 0; round < 20; round++)
        {
            foreach (var p in poses)
            {
                fish.SetPose(p);
            }
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    [Fact]
    public void QueriesAllocateNothing()
    {
        var a = new FishModel(FishSize.Default, new FishPose(Vector2.Zero, 0.3f, 0.2f, -0.1f, 0.3f));
        var b = new FishModel(FishSize.Default, new FishPose(new Vector2(40f, 30f), 1.8f, -0.2f, 0.1f, 0.2f));
        var field = new Field();
        var circle = new Circle(new Vector2(60f, 10f), 58f);
        var box = new Aabb(new Vector2(-20f, -20f), new Vector2(30f, 40f));
        var kdop = KDop8.FromAabb(box);
        var polygon = new ConvexPolygon([new(0f, 0f), new(50f, 10f), new(20f, 60f)]);
        var segment = new Segment(new Vector2(-100f, -100f), new Vector2(100f, 100f));
        Shape shape = polygon;
        Vector2[] points = [new(1490f, 0f), new(1510f, 5f)];
        var contacts = new FishContact[FishCollision.MaxContactsWithFish];
        int sink = 0;
        void All()
        {
            sink += FishCollision.Detect(a, circle).Intersect ? 1 : 0;
            sink += FishCollision.Detect(circle, a).Intersect ? 1 : 0;
            sink += FishCollision.Detect(a, box).Intersect ? 1 : 0;
            sink += FishCollision.Detect(box, a).Intersect ? 1 : 0;
            sink += FishCollision.Detect(a, kdop).Intersect ? 1 : 0;
            sink += FishCollision.Detect(kdop, a).Intersect ? 1 : 0;
            sink += FishCollision.Detect(a, polygon).Intersect ? 1 : 0;
            sink += FishCollision.Detect(polygon, a).Intersect ? 1 : 0;
            sink += FishCollision.Detect(a, segment).Intersect ? 1 : 0;
            sink += FishCollision.Detect(segment, a).Intersect ? 1 : 0;
            sink += FishCollision.Detect(a, b).Intersect ? 1 : 0;
            sink += FishCollision.Detect(a, shape).Intersect ? 1 : 0;
            sink += FishCollision.DetectAll(a, circle, contacts);
            sink += FishCollision.DetectAll(circle, a, contacts);
            sink += FishCollision.DetectAll(a, box, contacts);
            sink += FishCollision.DetectAll(a, kdop, contacts);
            sink += FishCollision.DetectAll(a, polygon, contacts);
            sink += FishCollision.DetectAll(polygon, a, contacts);
            sink += FishCollision.DetectAll(a, segment, contacts);
            sink += FishCollision.DetectAll(a, b, contacts);
            sink += FishCollision.DetectAll(shape, a, contacts);
            sink += field.Contain(circle).Intersect ? 1 : 0;
            sink += field.Contain(points).Intersect ? 1 : 0;
            sink += field.Contain(a).Intersect ? 1 : 0;
            sink += field.IsInGoal(circle, out int side) ? side : 0;
            sink += a.GetLeafBound(FishPart.Tail3).Vertices.Length;
        }

        Run(All);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int round = 0; round < 50; round++)
        {
            All();
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        Assert.True(sink > 0, "the queries found no contact at all: the scene is wrong");
    }

    // Warm up: let the JIT compile (and re-compile) everything before measuring.
    private static void Run(Action action)
    {
        for (int i = 0; i < 200; i++)
        {
            action();
        }
    }
}
