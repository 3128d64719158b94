namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>A response's verdict that a body is wedged (<see cref="MotionWorld.RejectMove"/>): the same rejected move as the motion world's own.</summary>
public sealed class MotionWorldRejectMoveTests
{
    [Fact]
    public void ARejectedFishGoesBackToWhereItBeganTheStepAtRest()
    {
        var world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        var start = new FishPose(new Vector2(1250f, 0f), 0.3f, 0.1f, -0.1f, 0.2f);
        BodyId fish = world.AddFish(FishSize.Default, start);

        // Between steps the joints change and the fish swims into the wall at x = 1500.
        world.SetJoints(fish, 0.2f, 0.2f, 0.2f);
        world.SetVelocity(fish, new Vector2(3000f, 0f), 1f);
        world.SetDrift(fish, new Vector2(0f, 50f), 0.5f);
        var handler = new RejectOnContact(fish);
        world.Step(0.1f, handler);

        Assert.Equal([fish], handler.Rejected);
        Assert.True(handler.ContactTime > 0.0);
        Assert.Equal(1, world.RejectedMoves);

        // Back at the pose the step began from, with the joints of before the step, and at rest.
        Assert.Equal(start, world.FishPoseOf(fish));
        Assert.Equal(Vector2.Zero, world.VelocityOf(fish));
        Assert.Equal(0f, world.AngularVelocityOf(fish));
        Assert.Equal(Vector2.Zero, world.DriftOf(fish));
        Assert.Equal(0f, world.AngularDriftOf(fish));
        Assert.Equal(0f, world.MeasureOverlap());
    }

    [Fact]
    public void WhileSettlingTheMoveRejectedIsTheLastStepsOne()
    {
        var world = new MotionWorld();
        BodyId a = world.AddCircle(50f, new Vector2(0f, 0f));
        BodyId b = world.AddCircle(50f, new Vector2(400f, 0f));
        world.SetVelocity(a, new Vector2(1000f, 0f));
        world.Step(0.1f, new RejectOnContact(default));
        Assert.Equal(new Vector2(100f, 0f), world.PositionOf(a));

        // A jump after the step lands a inside b; the response rejects a's move while settling.
        world.SetPose(a, new Vector2(350f, 0f), 0f);
        var handler = new RejectOnContact(a);
        world.Settle(handler);

        Assert.Equal([a], handler.Rejected);
        Assert.Equal(new Vector2(0f, 0f), world.PositionOf(a));
        Assert.Equal(new Vector2(400f, 0f), world.PositionOf(b));
        Assert.Equal(Vector2.Zero, world.VelocityOf(a));
    }

    [Fact]
    public void OutsideAStepOrForAStaticBodyItIsRefusedByName()
    {
        var world = new MotionWorld();
        BodyId ball = world.AddCircle(50f, Vector2.Zero);
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));

        var outside = Assert.Throws<ArgumentException>(() => world.RejectMove(ball));
        Assert.Equal("body", outside.ParamName);
        Assert.Contains("only from a handler", outside.Message, StringComparison.Ordinal);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.RejectMove(walls)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.RejectMove(default)).ParamName);
    }

    [Fact]
    public void WasRejectedTellsTheMoveRejectedInTheLastStepUntilTheNextBegins()
    {
        var world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(new Vector2(1250f, 0f), 0.3f, 0.1f, -0.1f, 0.2f));
        BodyId ball = world.AddCircle(50f, new Vector2(-1000f, 0f));
        world.SetVelocity(fish, new Vector2(3000f, 0f), 1f);
        Assert.False(world.WasRejected(fish));

        world.Step(0.1f, new RejectOnContact(fish));
        Assert.True(world.WasRejected(fish));
        Assert.False(world.WasRejected(ball));

        // Still so between steps (a Settle after the step sees it); the next step begins without it.
        Assert.True(world.WasRejected(fish));
        world.Step(0.1f, new RejectOnContact(default));
        Assert.False(world.WasRejected(fish));
    }

    [Fact]
    public void WasRejectedIsTrueExactlyForTheBodiesTheHandlerHeardOf()
    {
        // Balls in a box under a response that leaves 2 mm of every overlap: the motion world rejects
        // the moves of bodies left inside others at the end of a step. WasRejected must name the
        // same bodies as OnMoveRejected, step after step.
        var world = new MotionWorld();
        world.AddWalls(new Field(1000f, 800f, goalBlocks: false));
        var random = new Random(40);
        var balls = new List<BodyId>();
        for (int i = 0; i < 12; i++)
        {
            BodyId id = world.AddCircle(40f, new Vector2(-400f + (i % 4 * 260f), -250f + (i / 4 * 250f)));
            world.SetVelocity(id, new Vector2((float)(random.NextDouble() - 0.5) * 6000f, (float)(random.NextDouble() - 0.5) * 6000f));
            balls.Add(id);
        }

        int rejectedSteps = 0;
        for (int step = 0; step < 40; step++)
        {
            var handler = new RecordingHandler(leaveOverlap: 2f);
            world.Step(0.1f, handler);
            var heard = new HashSet<BodyId>(handler.Rejected);
            foreach (BodyId id in balls)
            {
                Assert.True(heard.Contains(id) == world.WasRejected(id), $"step {step}: ball {id} heard {heard.Contains(id)}, WasRejected {world.WasRejected(id)}");
            }

            rejectedSteps += heard.Count > 0 ? 1 : 0;
            foreach (BodyId id in balls)
            {
                if (world.VelocityOf(id) == Vector2.Zero)
                {
                    world.SetVelocity(id, new Vector2((float)(random.NextDouble() - 0.5) * 6000f, (float)(random.NextDouble() - 0.5) * 6000f));
                }
            }
        }

        Assert.True(rejectedSteps > 0, "no step rejected a move: the scene does not test WasRejected");
    }

    [Fact]
    public void WasRejectedOfABodyThatDoesNotMoveIsRefusedByName()
    {
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.WasRejected(walls)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.WasRejected(default)).ParamName);
    }

    // Rejects the move of one body at its first contact (none when the body is default); records what the motion world reports.
    private sealed class RejectOnContact(BodyId body) : IContactHandler
    {
        public List<BodyId> Rejected { get; } = [];

        public double ContactTime { get; private set; } = -1.0;

        public void OnContact(MotionWorld world, in Contact contact)
        {
            if (!body.IsNull && (contact.BodyA == body || contact.BodyB == body) && Rejected.Count == 0)
            {
                ContactTime = contact.Time;
                world.RejectMove(body);
            }
        }

        public void OnMoveRejected(MotionWorld world, BodyId rejected) => Rejected.Add(rejected);
    }
}
