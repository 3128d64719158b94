namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The count of exact pair tests (<see cref="MotionWorld.ExactTests"/>): a test counts when it runs,
/// not when the same pair at the same poses is answered from memory; a step whose bodies never come
/// near one another runs none; each step counts from 0; the same steps give the same count.
/// </summary>
public sealed class MotionWorldExactTestsTests
{
    [Fact]
    public void ATestCountsWhenItRunsNotWhenItIsRemembered()
    {
        var world = new MotionWorld();
        BodyId post = world.AddStatic(new Circle(new Vector2(0f, 0f), 50f));
        BodyId ball = world.AddCircle(58f, new Vector2(100f, 0f)); // 8 mm inside the post
        Assert.Equal(0, world.ExactTests);

        Assert.True(world.Detect(ball, post).Intersect);
        Assert.Equal(1, world.ExactTests);

        // Nothing moved: answered from memory, as many times as asked.
        world.Detect(ball, post);
        world.Detect(ball, post);
        Assert.Equal(1, world.ExactTests);

        // The ball moved: tested again, and the new answer is the new pose's.
        world.SetPose(ball, new Vector2(120f, 0f), 0f);
        Assert.False(world.Detect(ball, post).Intersect);
        Assert.Equal(2, world.ExactTests);
    }

    [Fact]
    public void BodiesThatNeverComeNearRunNoExactTest()
    {
        var world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId left = world.AddCircle(58f, new Vector2(-600f, 0f));
        BodyId right = world.AddCircle(58f, new Vector2(600f, 0f));
        world.AddStatic(new Circle(new Vector2(0f, 600f), 50f));
        world.SetVelocity(left, new Vector2(-200f, 0f));
        world.SetVelocity(right, new Vector2(200f, 0f));
        var handler = new RecordingHandler();
        for (int step = 0; step < 5; step++)
        {
            world.Step(0.1f, handler);
            Assert.Equal(0, world.ExactTests);
        }

        Assert.Empty(handler.Contacts);
    }

    [Fact]
    public void EachStepCountsItsOwnTests()
    {
        var world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId ball = world.AddCircle(58f, new Vector2(1500f - 58f - 20f, 0f));
        world.SetVelocity(ball, new Vector2(1000f, 0f));
        var handler = new RecordingHandler();
        world.Step(0.1f, handler);
        Assert.NotEmpty(handler.Contacts);
        Assert.True(world.ExactTests >= 1, $"{world.ExactTests} exact tests in a step with a contact");

        // The next step starts from 0: the ball, put back in the middle and sent away from every
        // wall, is never tested.
        world.SetPose(ball, Vector2.Zero, 0f);
        world.SetVelocity(ball, new Vector2(-100f, 0f));
        world.Step(0.1f, handler);
        Assert.Equal(0, world.ExactTests);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    public void TheSameStepsGiveTheSameCount(int threads)
    {
        // The crowd of every body kind the allocation and island tests step (fish, polygons, balls).
        MotionWorld first = MotionWorldAllocationTests.World(200), second = MotionWorldAllocationTests.World(200);
        second.Threads = threads;
        second.MinimumMoversForThreads = 1;
        var handler = new RecordingHandler { Record = false };
        long total = 0, events = 0;
        for (int step = 0; step < 40; step++)
        {
            first.Step(0.1f, handler);
            second.Step(0.1f, handler);
            Assert.Equal(first.Events, second.Events);
            for (int id = 0; id < first.BodyCount; id++)
            {
                Assert.Equal(first.PositionOf(first.IdAt(id)), second.PositionOf(second.IdAt(id)));
            }

            // On one thread the count is the same; on two, the islands' first samples count too
            // (every event was found by a sample's exact test), though memories differ.
            if (threads == 1)
            {
                Assert.Equal(first.ExactTests, second.ExactTests);
            }

            Assert.True(second.ExactTests >= second.Events, $"step {step}: {second.ExactTests} exact tests for {second.Events} events");
            total += second.ExactTests;
            events += second.Events;
        }

        Assert.True(events > 0, "no contact in 40 steps of a crowd");
        Assert.True(total >= events, $"{total} exact tests for {events} events");
        Assert.True(threads == 1 || second.Chunks > 1, "the crowd's islands should run on two threads");
    }

    [Fact]
    public void TestsRunOnTheIslandsThreadsCountAsOnOneThread()
    {
        // Two islands far apart, each a box gliding past a post: their bounding circles overlap
        // (so every sample tests them exactly) but the shapes stay 5 mm or more apart, so there is
        // no event and every test is a sample's, run on an island's thread when there are two.
        MotionWorld one = Posts(), two = Posts();
        two.Threads = 2;
        two.MinimumMoversForThreads = 1;
        var handler = new RecordingHandler();
        for (int step = 0; step < 5; step++)
        {
            one.Step(0.1f, handler);
            two.Step(0.1f, handler);
            Assert.True(one.ExactTests > 0, $"step {step}: no exact test");
            Assert.Equal(one.ExactTests, two.ExactTests);
            Assert.Equal(2, two.Chunks);
        }

        Assert.Empty(handler.Contacts);
    }

    private static MotionWorld Posts()
    {
        var box = new ConvexPolygon([new Vector2(-40f, -25f), new Vector2(40f, -25f), new Vector2(40f, 25f), new Vector2(-40f, 25f)]);
        var world = new MotionWorld();
        foreach (float x in new[] { -1000f, 1000f })
        {
            world.AddStatic(new Circle(new Vector2(x, 0f), 50f));
            BodyId glider = world.AddPolygon(box, new Vector2(x + 95f, 0f), 0f);
            world.SetVelocity(glider, new Vector2(0f, 10f));
        }

        return world;
    }
}
