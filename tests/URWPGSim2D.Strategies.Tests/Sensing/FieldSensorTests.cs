using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Strategies.Tests.Sensing;

/// <summary><see cref="FieldSensor"/> on hand-made scenes with known answers, its errors, and its allocations.</summary>
public sealed class FieldSensorTests
{
    [Fact]
    public void RayAlongTheAxisMeetsBallsAndBordersWhereTheyAre()
    {
        var snapshot = Scene(balls: [new BallView(0, new Vector2(500f, 0f), Vector2.Zero, 50f), new BallView(1, new Vector2(800f, 10f), Vector2.Zero, 30f)]);
        var sensor = Observed(snapshot);

        // A ray along +X: the first ball's near side at x = 450, fraction 450/1000.
        var hit = sensor.RayCast(Vector2.Zero, new Vector2(1000f, 0f));
        Assert.Equal(SensedBody.Ball(0), hit.Body);
        Assert.Equal(0.45f, hit.Result.Fraction, 5);
        Assert.Equal(new Vector2(-1f, 0f), hit.Result.Normal);

        // Ignoring ball 0: ball 1's circle at x = 800 − √(30² − 10²).
        var next = sensor.RayCast(Vector2.Zero, new Vector2(1000f, 0f), ignore: SensedBody.Ball(0));
        Assert.Equal(SensedBody.Ball(1), next.Body);
        Assert.Equal((800f - MathF.Sqrt(800f)) / 1000f, next.Result.Fraction, 5);

        // Borders only: the right border at x = 1500.
        var wall = sensor.RayCast(Vector2.Zero, new Vector2(2000f, 0f), SensedKinds.Walls);
        Assert.Equal(SensedBody.Wall(1), wall.Body);
        Assert.Equal(0.75f, wall.Result.Fraction, 5);

        // Every entry, nearest first.
        Span<SensedHit> all = stackalloc SensedHit[8];
        int n = sensor.RayCastAll(Vector2.Zero, new Vector2(2000f, 0f), all);
        Assert.Equal(3, n);
        Assert.Equal([SensedBody.Ball(0), SensedBody.Ball(1), SensedBody.Wall(1)], all[..n].ToArray().Select(h => h.Body));

        // A ray that stays clear misses.
        Assert.False(sensor.RayCast(new Vector2(0f, 500f), new Vector2(1000f, 500f), SensedKinds.Balls).Hit);
    }

    [Fact]
    public void DistancesBetweenDiscsAndToBordersAreAnalytic()
    {
        var snapshot = Scene(balls: [new BallView(0, new Vector2(-300f, 400f), Vector2.Zero, 40f), new BallView(1, new Vector2(0f, 0f), Vector2.Zero, 60f)],
            obstacles: [new ObstacleView(0, ObstacleKind.Round, new Vector2(900f, -600f), 0f, 0f, 0f, 100f)]);
        var sensor = Observed(snapshot);
        Assert.Equal(500f - 40f - 60f, sensor.Distance(SensedBody.Ball(0), SensedBody.Ball(1)).Distance, 3);
        Assert.Equal(Vector2.Distance(new Vector2(900f, -600f), Vector2.Zero) - 160f, sensor.Distance(SensedBody.Obstacle(0), SensedBody.Ball(1)).Distance, 3);

        // Ball 0's circle is 1000 − 400 − 40 = 560 from the bottom border (Z = +1000).
        Assert.Equal(560f, sensor.Distance(SensedBody.Ball(0), SensedBody.Wall(2)).Distance, 3);

        // The clearance of a point is its gap to the nearest border or obstacle.
        Assert.Equal(100f, sensor.Clearance(new Vector2(1400f, 900f)), 3);
        Assert.Equal(50f, sensor.Clearance(new Vector2(900f, -450f)), 3);
        Assert.Equal(0f, sensor.Clearance(new Vector2(900f, -600f)));
        var near = sensor.Nearest(new Vector2(-300f, 300f));
        Assert.Equal(SensedBody.Ball(0), near.Body);
        Assert.Equal(60f, near.Distance, 3);
    }

    [Fact]
    public void AFishIsSeenByItsParts()
    {
        var fish = new FishView(0, 0, new Vector2(0f, 0f), 0f, 0f, 0f, 160f, 30f, Decision.Stop);
        var snapshot = Scene(fish: [fish]);
        var sensor = Observed(snapshot);

        // The head tip is L/2 + head = 110 mm ahead of the centre: a ray from the front meets the head.
        var head = sensor.RayCast(new Vector2(500f, 0f), new Vector2(0f, 0f), SensedKinds.Fish);
        Assert.Equal(SensedBody.Fish(0), head.Body);
        Assert.Equal(FishPart.Body, head.Result.Part);
        Assert.Equal(110f, head.Result.Point.X, 3);

        // From behind, the caudal fin's lobes or the last tail segment.
        var tail = sensor.RayCast(new Vector2(-800f, 0f), new Vector2(0f, 0f), SensedKinds.Fish);
        Assert.True(tail.Result.Part is FishPart.Tail3 or FishPart.LeftCaudal or FishPart.RightCaudal, tail.ToString());

        // A ray out of the fish's own head passes its own fish when it is ignored, and it starts inside it anyway.
        Assert.False(sensor.RayCast(new Vector2(100f, 0f), new Vector2(1000f, 0f), SensedKinds.Fish).Hit);
        Assert.False(sensor.RayCast(new Vector2(-800f, 0f), new Vector2(800f, 0f), SensedKinds.Fish, SensedBody.Fish(0)).Hit);

        // The model is the library's, at the view's pose.
        Assert.Equal(new FishPose(Vector2.Zero, 0f), sensor.GetFish(0).Pose);
        Assert.Equal(0f, sensor.Distance(SensedBody.Fish(0), new Vector2(0f, 0f)).Distance);
    }

    [Fact]
    public void ObserveFollowsTheSnapshotEveryCycle()
    {
        var snapshot = Scene(balls: [new BallView(0, new Vector2(0f, 0f), Vector2.Zero, 50f)]);
        var sensor = Observed(snapshot);
        Assert.Equal(0f, sensor.Distance(SensedBody.Ball(0), Vector2.Zero).Distance);
        snapshot.BallBuffer[0] = new BallView(0, new Vector2(300f, 0f), Vector2.Zero, 50f);
        snapshot.SetHeader(2, [0, 0]);
        sensor.Observe(snapshot);
        Assert.Equal(250f, sensor.Distance(SensedBody.Ball(0), Vector2.Zero).Distance, 3);
        Assert.Equal(2, sensor.Cycle);
        Span<SensedBody> found = stackalloc SensedBody[4];
        Assert.Equal(1, sensor.Overlap(new Circle(new Vector2(300f, 0f), 10f), found));
        Assert.Equal(SensedBody.Ball(0), found[0]);
        Assert.Equal(0, sensor.Overlap(new Circle(Vector2.Zero, 10f), found));
    }

    [Fact]
    public void BadQueriesAreRefusedWithTheirParameter()
    {
        var sensor = new FieldSensor();
        Assert.Throws<InvalidOperationException>(() => sensor.RayCast(Vector2.Zero, Vector2.One));
        Assert.Throws<ArgumentNullException>(() => sensor.Observe(null!));
        sensor.Observe(Scene());
        Assert.Equal("to", Assert.Throws<ArgumentException>(() => sensor.RayCast(Vector2.Zero, new Vector2(float.NaN, 0f))).ParamName);
        Assert.Equal("point", Assert.Throws<ArgumentException>(() => sensor.Nearest(new Vector2(float.PositiveInfinity, 0f))).ParamName);
        Assert.Equal("kinds", Assert.Throws<ArgumentException>(() => sensor.Nearest(Vector2.Zero, (SensedKinds)64)).ParamName);
        Assert.Equal("b", Assert.Throws<ArgumentException>(() => sensor.Distance(SensedBody.Wall(0), SensedBody.Ball(3))).ParamName);
        Assert.Equal("a", Assert.Throws<ArgumentException>(() => sensor.Distance(SensedBody.None, SensedBody.Wall(0))).ParamName);
        Assert.Equal("index", Assert.Throws<ArgumentException>(() => sensor.GetFish(0)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => sensor.GetShape(SensedBody.Wall(4))).ParamName);
        Assert.False(sensor.Nearest(Vector2.Zero, SensedKinds.None).Body.Exists);
        Assert.Equal(float.PositiveInfinity, sensor.Nearest(Vector2.Zero, SensedKinds.Balls).Distance);
    }

    [Fact]
    public void ObservingAndQueryingAllocateNothing()
    {
        var rng = new Random(2705);
        var s = SensedScene.Random(rng, fishCount: 4, ballCount: 9);
        var sensor = new FieldSensor();
        Span<SensedBody> bodies = stackalloc SensedBody[16];
        Span<SensedHit> hits = stackalloc SensedHit[16];
        void Round(Span<SensedBody> bodies, Span<SensedHit> hits)
        {
            sensor.Observe(s.Snapshot);
            for (int k = 0; k < 50; k++)
            {
                Vector2 p = new(-1400f + (56f * k), -900f + (36f * k));
                sensor.RayCast(p, -p, ignore: SensedBody.Fish(1));
                sensor.RayCastAll(p, -p, hits);
                sensor.Overlap(new Circle(p, 200f), bodies);
                sensor.Nearest(p, ignore: SensedBody.Fish(0));
                sensor.Clearance(p);
                sensor.Distance(SensedBody.Fish(k % 4), SensedBody.Ball(k % 9));
                sensor.Distance(SensedBody.Fish(k % 4), SensedBody.Fish((k + 1) % 4));
            }
        }

        Round(bodies, hits); // builds the models and shapes
        Round(bodies, hits); // the broad phases' first moves size their buffers
        s.Snapshot.FishBuffer[0] = s.Snapshot.FishBuffer[0] with { Position = new Vector2(10f, 20f), Joint1 = 0.3f };
        long before = GC.GetAllocatedBytesForCurrentThread();
        Round(bodies, hits);
        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    internal static MatchSnapshot Scene(BallView[]? balls = null, ObstacleView[]? obstacles = null, FishView[]? fish = null)
    {
        balls ??= [];
        fish ??= [];
        var snapshot = new MatchSnapshot(fish.Length, balls.Length, obstacles ?? [], 3000f, 2000f);
        balls.CopyTo(snapshot.BallBuffer);
        fish.CopyTo(snapshot.FishBuffer);
        snapshot.SetHeader(1, [0, 0]);
        return snapshot;
    }

    private static FieldSensor Observed(MatchSnapshot snapshot)
    {
        var sensor = new FieldSensor();
        sensor.Observe(snapshot);
        return sensor;
    }
}
