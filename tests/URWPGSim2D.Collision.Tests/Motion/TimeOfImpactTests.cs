namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>The pair-level time of impact (the motion world's detection on two bodies) against analytic times of first contact.</summary>
public sealed class TimeOfImpactTests
{
    private const float Tolerance = MotionTolerances.TimeOfImpactTolerance;

    [Fact]
    public void BallMeetsARestingBallWhenTheGapCloses()
    {
        // 300 mm between centres, radii 50: the 200 mm gap closes at 1,000 mm/s after 0.2 s.
        TimeOfImpactResult r = TimeOfImpact.Find(
            MovingBody.Circle(new Circle(Vector2.Zero, 50f), new Vector2(1000f, 0f)),
            MovingBody.Static(new Circle(new Vector2(300f, 0f), 50f)),
            0.3f);

        Assert.True(r.Hit);
        Assert.InRange(r.Time, 0.2f, 0.2f + (Tolerance / 1000f) + 1e-6f);
        Assert.InRange(r.Result.Depth, 0f, Tolerance + 1e-3f);

        // The translation moves the first body back, along −X.
        Assert.True(r.Result.MinimumTranslationVector.X <= 0f);
        Assert.Null(r.PartA);
        Assert.Null(r.PartB);
    }

    [Fact]
    public void SwappingTheBodiesGivesTheSameTimeAndTheOppositeTranslation()
    {
        MovingBody ball = MovingBody.Circle(new Circle(Vector2.Zero, 50f), new Vector2(1000f, 0f));
        MovingBody rest = MovingBody.Static(new Circle(new Vector2(300f, 0f), 50f));

        TimeOfImpactResult ab = TimeOfImpact.Find(ball, rest, 0.3f);
        TimeOfImpactResult ba = TimeOfImpact.Find(rest, ball, 0.3f);

        Assert.True(ab.Hit && ba.Hit);
        Assert.Equal(ab.Time, ba.Time);
        Assert.Equal(ab.Result.Swapped(), ba.Result);
    }

    [Fact]
    public void BallMeetsAWall()
    {
        // The ball's edge is 142 mm from the wall at x = 1500 and travels 1,000 mm/s.
        TimeOfImpactResult r = TimeOfImpact.Find(
            MovingBody.Circle(new Circle(new Vector2(1300f, 0f), 58f), new Vector2(1000f, 0f)),
            MovingBody.Walls(new Field(3000f, 2000f, goalBlocks: false)),
            0.5f);

        Assert.True(r.Hit);
        Assert.InRange(r.Time, 0.142f - 1e-6f, 0.142f + (Tolerance / 1000f) + 1e-6f);
    }

    [Fact]
    public void BodiesThatOverlapAtTheStartTouchAtTimeZero()
    {
        TimeOfImpactResult r = TimeOfImpact.Find(
            MovingBody.Circle(new Circle(Vector2.Zero, 50f), new Vector2(-1000f, 0f)),
            MovingBody.Circle(new Circle(new Vector2(90f, 0f), 50f), Vector2.Zero),
            0.1f);

        Assert.True(r.Hit);
        Assert.Equal(0f, r.Time);
        Assert.Equal(10f, r.Result.Depth, 1e-3f);
    }

    [Fact]
    public void BodiesThatPassEachOtherDoNotTouch()
    {
        TimeOfImpactResult r = TimeOfImpact.Find(
            MovingBody.Circle(new Circle(new Vector2(0f, 0f), 50f), new Vector2(2000f, 0f)),
            MovingBody.Circle(new Circle(new Vector2(1000f, 101f), 50f), new Vector2(-2000f, 0f)),
            1f);

        Assert.False(r.Hit);
        Assert.Equal(TimeOfImpactResult.NoContact, r);
    }

    [Fact]
    public void AFastThinPolygonDoesNotTunnelThroughAThinWall()
    {
        // A 4 mm thick rod crossing a 2 mm thick static bar at 20,000 mm/s: the contact is when their faces meet.
        var rod = new ConvexPolygon([new Vector2(-2f, -40f), new Vector2(2f, -40f), new Vector2(2f, 40f), new Vector2(-2f, 40f)]);
        var bar = new ConvexPolygon([new Vector2(499f, -200f), new Vector2(501f, -200f), new Vector2(501f, 200f), new Vector2(499f, 200f)]);
        TimeOfImpactResult r = TimeOfImpact.Find(
            MovingBody.Polygon(rod, Vector2.Zero, 0f, new Vector2(20000f, 0f), 0f),
            MovingBody.Static(bar),
            0.1f);

        // The faces meet after 497 mm, at 0.02485 s.
        Assert.True(r.Hit);
        Assert.InRange(r.Time, 0.02485f - 1e-6f, 0.02485f + (Tolerance / 20000f) + 1e-6f);
    }

    [Fact]
    public void AFishMeetsABallWithItsHeadAndIsLeftAsItWas()
    {
        var pose = new FishPose(new Vector2(-600f, 0f), 0f, 0f, 0f, 0f);
        var model = new FishModel(FishSize.Default, pose);
        TimeOfImpactResult r = TimeOfImpact.Find(
            MovingBody.Fish(model, new Vector2(500f, 0f), 0f),
            MovingBody.Circle(new Circle(new Vector2(0f, 0f), 58f), Vector2.Zero),
            2f);

        Assert.True(r.Hit);
        Assert.Equal(FishPart.Body, r.PartA);
        Assert.Null(r.PartB);
        Assert.Equal(pose, model.Pose);

        // Brute force: the fish moved to the reported time (and a tolerance before it) against the ball.
        Assert.True(Overlaps(pose, r.Time, 58f));
        Assert.False(Overlaps(pose, r.Time - (Tolerance / 500f) - 1e-4f, 58f));
    }

    [Fact]
    public void TwoMovingBallsMeetAtTheAnalyticTime()
    {
        // Two balls on straight lines first touch at the smaller root of |Δp + Δv·t| = r₁ + r₂
        // (1,000 cases from a fixed seed). The pair is sampled at most r₁ + r₂ of relative travel
        // apart, so a graze whose chord is shorter than that may pass between two samples.
        var random = new Random(20261204);
        for (int i = 0; i < 1000; i++)
        {
            var start = new Vector2(Uniform(random, -800f, 800f), Uniform(random, -800f, 800f));
            var velocity = new Vector2(Uniform(random, -3000f, 3000f), Uniform(random, -3000f, 3000f));
            float r1 = Uniform(random, 20f, 80f), r2 = Uniform(random, 20f, 80f);
            float reach = r1 + r2;
            if (start.Length() <= reach + 1f)
            {
                continue; // overlapping or touching at the start: another test
            }

            double? exact = FirstTouch(start, velocity, reach, 0.5);
            TimeOfImpactResult r = TimeOfImpact.Find(
                MovingBody.Circle(new Circle(start, r1), velocity),
                MovingBody.Circle(new Circle(Vector2.Zero, r2), Vector2.Zero),
                0.5f);
            double slack = (Tolerance / Math.Max(velocity.Length(), 1f)) + 1e-5;
            double closest = Closest(start, velocity, 0.5);
            bool graze = closest >= reach - Tolerance || 2.0 * Math.Sqrt(Math.Max(0.0, ((double)reach * reach) - (closest * closest))) <= reach;
            string name = $"case {i}: start {start}, velocity {velocity}, radii {r1}, {r2}, exact {exact}, found {r.Hit} at {r.Time}";
            if (r.Hit)
            {
                Assert.True(exact.HasValue || graze, name);
                Assert.True(!exact.HasValue || (r.Time >= exact.Value - 1e-5 && r.Time <= exact.Value + slack), name);
            }
            else
            {
                Assert.True(!exact.HasValue || graze || exact.Value > 0.5 - slack, name);
            }
        }
    }

    [Fact]
    public void BadArgumentsAreRejectedByName()
    {
        MovingBody ball = MovingBody.Circle(new Circle(Vector2.Zero, 50f), new Vector2(1000f, 0f));
        MovingBody rest = MovingBody.Static(new Circle(new Vector2(300f, 0f), 50f));

        Assert.Equal("seconds", Assert.Throws<ArgumentException>(() => TimeOfImpact.Find(ball, rest, 0f)).ParamName);
        Assert.Equal("seconds", Assert.Throws<ArgumentException>(() => TimeOfImpact.Find(ball, rest, float.NaN)).ParamName);
        Assert.Equal("seconds", Assert.Throws<ArgumentException>(() => TimeOfImpact.Find(ball, rest, float.PositiveInfinity)).ParamName);
        Assert.Equal("b", Assert.Throws<ArgumentException>(() => TimeOfImpact.Find(rest, rest, 1f)).ParamName);
        Assert.Equal("a", Assert.Throws<ArgumentException>(() => TimeOfImpact.Find(default, rest, 1f)).ParamName);
        Assert.Equal("b", Assert.Throws<ArgumentException>(() => TimeOfImpact.Find(ball, default, 1f)).ParamName);
    }

    private static float Uniform(Random random, float lo, float hi) => lo + ((hi - lo) * (float)random.NextDouble());

    // The first t in [0, limit] with |start + velocity·t| = reach (start is outside), or null.
    private static double? FirstTouch(Vector2 start, Vector2 velocity, float reach, double limit)
    {
        double a = Vector2.Dot(velocity, velocity);
        double b = 2.0 * Vector2.Dot(start, velocity);
        double c = Vector2.Dot(start, start) - ((double)reach * reach);
        double disc = (b * b) - (4.0 * a * c);
        if (a == 0.0 || disc < 0.0)
        {
            return null;
        }

        double t = (-b - Math.Sqrt(disc)) / (2.0 * a);
        return t >= 0.0 && t <= limit ? t : null;
    }

    // The closest distance of the path start + velocity·t over [0, limit] to the origin.
    private static double Closest(Vector2 start, Vector2 velocity, double limit)
    {
        double a = Vector2.Dot(velocity, velocity);
        double t = a == 0.0 ? 0.0 : Math.Clamp(-Vector2.Dot(start, velocity) / a, 0.0, limit);
        return (start + (velocity * (float)t)).Length();
    }

    // Whether the fish, moved on at 500 mm/s for the time, overlaps a ball at the origin (a world tested in place, no motion).
    private static bool Overlaps(FishPose start, float seconds, float radius)
    {
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, start.Translated(new Vector2(500f * seconds, 0f)));
        BodyId ball = world.AddCircle(radius, Vector2.Zero);
        return world.Detect(fish, ball).Depth > MotionTolerances.ContactSlop;
    }
}
