namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>A response's verdict that a body is wedged (<see cref="Stepper.RejectMove"/>): the same rejected move as the stepper's own.</summary>
public sealed class StepperRejectMoveTests
{
    [Fact]
    public void ARejectedFishGoesBackToWhereItBeganTheStepAtRest()
    {
        var stepper = new Stepper();
        stepper.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        var start = new FishPose(new Vector2(1250f, 0f), 0.3f, 0.1f, -0.1f, 0.2f);
        BodyId fish = stepper.AddFish(FishSize.Default, start);

        // Between steps the joints change and the fish swims into the wall at x = 1500.
        stepper.SetJoints(fish, 0.2f, 0.2f, 0.2f);
        stepper.SetVelocity(fish, new Vector2(3000f, 0f), 1f);
        stepper.SetDrift(fish, new Vector2(0f, 50f), 0.5f);
        var handler = new RejectOnContact(fish);
        stepper.Step(0.1f, handler);

        Assert.Equal([fish], handler.Rejected);
        Assert.True(handler.ContactTime > 0.0);
        Assert.Equal(1, stepper.RejectedMoves);

        // Back at the pose the step began from, with the joints of before the step, and at rest.
        Assert.Equal(start, stepper.FishPoseOf(fish));
        Assert.Equal(Vector2.Zero, stepper.VelocityOf(fish));
        Assert.Equal(0f, stepper.AngularVelocityOf(fish));
        Assert.Equal(Vector2.Zero, stepper.DriftOf(fish));
        Assert.Equal(0f, stepper.AngularDriftOf(fish));
        Assert.Equal(0f, stepper.MeasureOverlap());
    }

    [Fact]
    public void WhileSettlingTheMoveRejectedIsTheLastStepsOne()
    {
        var stepper = new Stepper();
        BodyId a = stepper.AddCircle(50f, new Vector2(0f, 0f));
        BodyId b = stepper.AddCircle(50f, new Vector2(400f, 0f));
        stepper.SetVelocity(a, new Vector2(1000f, 0f));
        stepper.Step(0.1f, new RejectOnContact(default));
        Assert.Equal(new Vector2(100f, 0f), stepper.PositionOf(a));

        // A jump after the step lands a inside b; the response rejects a's move while settling.
        stepper.SetPose(a, new Vector2(350f, 0f), 0f);
        var handler = new RejectOnContact(a);
        stepper.Settle(handler);

        Assert.Equal([a], handler.Rejected);
        Assert.Equal(new Vector2(0f, 0f), stepper.PositionOf(a));
        Assert.Equal(new Vector2(400f, 0f), stepper.PositionOf(b));
        Assert.Equal(Vector2.Zero, stepper.VelocityOf(a));
    }

    [Fact]
    public void OutsideAStepOrForAStaticBodyItIsRefusedByName()
    {
        var stepper = new Stepper();
        BodyId ball = stepper.AddCircle(50f, Vector2.Zero);
        BodyId walls = stepper.AddWalls(new Field(3000f, 2000f, goalBlocks: false));

        var outside = Assert.Throws<ArgumentException>(() => stepper.RejectMove(ball));
        Assert.Equal("body", outside.ParamName);
        Assert.Contains("only from a handler", outside.Message, StringComparison.Ordinal);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.RejectMove(walls)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.RejectMove(default)).ParamName);
    }

    [Fact]
    public void WasRejectedTellsTheMoveRejectedInTheLastStepUntilTheNextBegins()
    {
        var stepper = new Stepper();
        stepper.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId fish = stepper.AddFish(FishSize.Default, new FishPose(new Vector2(1250f, 0f), 0.3f, 0.1f, -0.1f, 0.2f));
        BodyId ball = stepper.AddCircle(50f, new Vector2(-1000f, 0f));
        stepper.SetVelocity(fish, new Vector2(3000f, 0f), 1f);
        Assert.False(stepper.WasRejected(fish));

        stepper.Step(0.1f, new RejectOnContact(fish));
        Assert.True(stepper.WasRejected(fish));
        Assert.False(stepper.WasRejected(ball));

        // Still so between steps (a Settle after the step sees it); the next step begins without it.
        Assert.True(stepper.WasRejected(fish));
        stepper.Step(0.1f, new RejectOnContact(default));
        Assert.False(stepper.WasRejected(fish));
    }

    [Fact]
    public void WasRejectedIsTrueExactlyForTheBodiesTheHandlerHeardOf()
    {
        // Balls in a box under a response that leaves 2 mm of every overlap: the stepper rejects
        // the moves of bodies left inside others at the end of a step. WasRejected must name the
        // same bodies as OnMoveRejected, step after step.
        var stepper = new Stepper();
        stepper.AddWalls(new Field(1000f, 800f, goalBlocks: false));
        var random = new Random(40);
        var balls = new List<BodyId>();
        for (int i = 0; i < 12; i++)
        {
            BodyId id = stepper.AddCircle(40f, new Vector2(-400f + (i % 4 * 260f), -250f + (i / 4 * 250f)));
            stepper.SetVelocity(id, new Vector2((float)(random.NextDouble() - 0.5) * 6000f, (float)(random.NextDouble() - 0.5) * 6000f));
            balls.Add(id);
        }

        int rejectedSteps = 0;
        for (int step = 0; step < 40; step++)
        {
            var handler = new RecordingHandler(leaveOverlap: 2f);
            stepper.Step(0.1f, handler);
            var heard = new HashSet<BodyId>(handler.Rejected);
            foreach (BodyId id in balls)
            {
                Assert.True(heard.Contains(id) == stepper.WasRejected(id), $"step {step}: ball {id} heard {heard.Contains(id)}, WasRejected {stepper.WasRejected(id)}");
            }

            rejectedSteps += heard.Count > 0 ? 1 : 0;
            foreach (BodyId id in balls)
            {
                if (stepper.VelocityOf(id) == Vector2.Zero)
                {
                    stepper.SetVelocity(id, new Vector2((float)(random.NextDouble() - 0.5) * 6000f, (float)(random.NextDouble() - 0.5) * 6000f));
                }
            }
        }

        Assert.True(rejectedSteps > 0, "no step rejected a move: the scene does not test WasRejected");
    }

    [Fact]
    public void WasRejectedOfABodyThatDoesNotMoveIsRefusedByName()
    {
        var stepper = new Stepper();
        BodyId walls = stepper.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.WasRejected(walls)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.WasRejected(default)).ParamName);
    }

    // Rejects the move of one body at its first contact (none when the body is default); records what the stepper reports.
    private sealed class RejectOnContact(BodyId body) : IContactHandler
    {
        public List<BodyId> Rejected { get; } = [];

        public double ContactTime { get; private set; } = -1.0;

        public void OnContact(Stepper stepper, in Contact contact)
        {
            if (!body.IsNull && (contact.BodyA == body || contact.BodyB == body) && Rejected.Count == 0)
            {
                ContactTime = contact.Time;
                stepper.RejectMove(body);
            }
        }

        public void OnMoveRejected(Stepper stepper, BodyId rejected) => Rejected.Add(rejected);
    }
}
