namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>The world motion world: contacts at their analytic times, in time order, no tunnelling, its API's checks.</summary>
public sealed class MotionWorldTests
{
    [Fact]
    public void BallMeetsTheWallAtItsTimeOfFirstContact()
    {
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId ball = world.AddCircle(50f, new Vector2(1400f, 0f));
        world.SetVelocity(ball, new Vector2(2000f, 0f));
        var handler = new RecordingHandler();
        world.Step(0.1f, handler);

        // The ball's edge is 50 mm from the wall and travels 200 mm in the step: contact at 1/4.
        Contact c = Assert.Single(handler.Contacts);
        Assert.Equal(ball, c.BodyA);
        Assert.Equal(walls, c.BodyB);
        Assert.InRange(c.Time, 0.25, 0.25 + (0.25 / 200.0));
        Assert.True(world.PositionOf(ball).X <= 1450f + 1e-3f);
        Assert.Equal(0f, world.VelocityOf(ball).X);
    }

    [Fact]
    public void ContactsComeInTimeOrderAndEachBallStopsAtItsObstacle()
    {
        var world = new MotionWorld();
        var obstacles = new float[] { 130f, 60f, 170f, 95f };
        for (int i = 0; i < obstacles.Length; i++)
        {
            world.AddStatic(new Circle(new Vector2(0f, i * 300f), 50f));
        }

        var balls = new BodyId[obstacles.Length];
        for (int i = 0; i < obstacles.Length; i++)
        {
            // Centre distance at contact is 100 mm: ball i starts 100 + gap_i to the left, at 2000 mm/s.
            balls[i] = world.AddCircle(50f, new Vector2(-100f - obstacles[i], i * 300f));
            world.SetVelocity(balls[i], new Vector2(2000f, 0f));
        }

        var handler = new RecordingHandler();
        world.Step(0.1f, handler);
        Assert.Equal(obstacles.Length, handler.Contacts.Count);
        for (int k = 1; k < handler.Contacts.Count; k++)
        {
            Assert.True(handler.Contacts[k - 1].Time <= handler.Contacts[k].Time, $"contact {k} comes before contact {k - 1}");
        }

        foreach (Contact c in handler.Contacts)
        {
            int i = Array.IndexOf(balls, c.BodyA);
            Assert.InRange(c.Time, obstacles[i] / 200.0, (obstacles[i] + 0.25) / 200.0);
        }
    }

    [Theory]
    [InlineData(5000f, 20f)]
    [InlineData(20000f, 5f)]
    public void AFastBallDoesNotPassThroughAThinWall(float speed, float thickness)
    {
        var world = new MotionWorld();
        world.AddStatic(new Aabb(new Vector2(300f, -500f), new Vector2(300f + thickness, 500f)));
        BodyId ball = world.AddCircle(20f, new Vector2(0f, 0f));
        world.SetVelocity(ball, new Vector2(speed, 0f));
        var handler = new RecordingHandler();
        world.Step(0.1f, handler);
        Assert.Single(handler.Contacts);
        Assert.True(world.PositionOf(ball).X <= 280f + 1e-3f, $"ball at {world.PositionOf(ball).X}");
    }

    [Fact]
    public void ASpinningPolygonSweepsIntoABallItWouldMissWithoutTurning()
    {
        var world = new MotionWorld();
        var bar = new ConvexPolygon([new Vector2(-200f, -5f), new Vector2(200f, -5f), new Vector2(200f, 5f), new Vector2(-200f, 5f)]);
        BodyId polygon = world.AddPolygon(bar, Vector2.Zero, 0f);
        BodyId ball = world.AddCircle(10f, new Vector2(0f, 150f));
        world.SetVelocity(polygon, Vector2.Zero, MathF.PI * 10f); // half a turn in 0.1 s
        var handler = new RecordingHandler();
        world.Step(0.1f, handler);
        // The bar keeps turning (the test response keeps its spin) and pushes the ball on: the first contact is the one that matters.
        Contact c = handler.Contacts[0];
        Assert.Equal(polygon, c.BodyA);
        Assert.Equal(ball, c.BodyB);

        // The bar's far edge (y = +5 side, reach ~150) meets the ball when it has turned by about asin(15 / 150)... the ball sits
        // on the +Z axis: the bar (half-width 5) reaches the ball's edge (10) at an angle of π/2 − asin(15/150) from +X.
        double angle = (Math.PI / 2) - Math.Asin(15.0 / 150.0);
        double expected = angle / Math.PI;
        Assert.InRange(c.Time, expected - 0.01, expected + 0.002);
    }

    [Fact]
    public void TheSameWorldGivesTheSameContactsBitForBit()
    {
        static (MotionWorld, RecordingHandler) Run()
        {
            var world = new MotionWorld();
            world.AddWalls(new Field());
            foreach (Aabb block in new Field().GoalBlocks)
            {
                world.AddStatic(block);
            }

            var random = new Random(5);
            for (int i = 0; i < 40; i++)
            {
                BodyId b = world.AddCircle(30f, new Vector2((float)(random.NextDouble() * 2400 - 1200), (float)(random.NextDouble() * 1600 - 800)));
                world.SetVelocity(b, new Vector2((float)(random.NextDouble() * 4000 - 2000), (float)(random.NextDouble() * 4000 - 2000)));
            }

            BodyId fish = world.AddFish(FishSize.Default, new FishPose(new Vector2(100f, 50f), 0.3f, 0.2f, -0.1f, 0.3f));
            world.SetVelocity(fish, new Vector2(300f, 100f), 0.4f);
            var handler = new RecordingHandler(0.5f);
            for (int k = 0; k < 20; k++)
            {
                world.Step(0.1f, handler);
            }

            return (world, handler);
        }

        var (s1, h1) = Run();
        var (s2, h2) = Run();
        Assert.True(h1.Contacts.Count > 20);
        Assert.Equal(h1.Contacts.Count, h2.Contacts.Count);
        for (int i = 0; i < h1.Contacts.Count; i++)
        {
            try
            {
                Assert.Equal(h1.Contacts[i].Time, h2.Contacts[i].Time);
                Assert.Equal(h1.Contacts[i].Result, h2.Contacts[i].Result);
                Assert.Equal(h1.Contacts[i].BodyA.Index, h2.Contacts[i].BodyA.Index);
                Assert.Equal(h1.Contacts[i].BodyB.Index, h2.Contacts[i].BodyB.Index);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(5, i, e);
            }
        }

        for (int b = 0; b < s1.BodyCount; b++)
        {
            Assert.Equal(s1.PositionOf(s1.IdAt(b)), s2.PositionOf(s2.IdAt(b)));
        }
    }

    [Fact]
    public void BadArgumentsNameTheFieldAndValue()
    {
        var world = new MotionWorld();
        BodyId wall = world.AddStatic(new Circle(Vector2.Zero, 5f));
        BodyId ball = world.AddCircle(5f, new Vector2(100f, 0f));
        var handler = new RecordingHandler();
        Assert.Contains("positive and finite", Assert.Throws<ArgumentException>(() => world.Step(0f, handler)).Message);
        Assert.Throws<ArgumentNullException>(() => world.Step(0.1f, null!));
        BodyId elsewhere = new MotionWorld().AddCircle(5f, Vector2.Zero);
        Assert.Contains("body 0 is not a body of this motion world", Assert.Throws<ArgumentException>(() => world.PositionOf(elsewhere)).Message);
        Assert.Contains("default(BodyId) names no body", Assert.Throws<ArgumentException>(() => world.PositionOf(default)).Message);
        Assert.Contains("Static", Assert.Throws<ArgumentException>(() => world.SetVelocity(wall, Vector2.One)).Message);
        Assert.Contains("not a Fish", Assert.Throws<ArgumentException>(() => world.SetJoints(ball, 0f, 0f, 0f)).Message);
        Assert.Contains("finite", Assert.Throws<ArgumentException>(() => world.SetVelocity(ball, new Vector2(float.NaN, 0f))).Message);
        Assert.Contains("itself", Assert.Throws<ArgumentException>(() => world.Detect(ball, ball)).Message);
        world.AddWalls(new Field());
        Assert.Contains("walls already", Assert.Throws<ArgumentException>(() => world.AddWalls(new Field())).Message);
    }
}
