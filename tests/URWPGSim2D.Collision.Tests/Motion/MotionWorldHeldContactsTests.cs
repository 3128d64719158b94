namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// Held contacts (<c>MotionWorld.HeldSubSteps</c>): a pair that touches and cannot pass through
/// itself within a sub-step is tested at every sub-step's end and answered there, as a pressing
/// contact, instead of at its own time of first contact; a pair that is not touching, or is too
/// fast for a sub-step, keeps its own clock. Checked against the analytic times and depths of a
/// ball pressed against a wall, a fast ball against a thin bar, random crowds (no overlap left,
/// the same contacts on one and two threads and from run to run) and refusals by name.
/// </summary>
public sealed class MotionWorldHeldContactsTests
{
    private const float Seconds = 0.1f;

    [Fact]
    public void ABallPressedAgainstAWallIsAnsweredAtTheSubStepsEndsAndAgainAtItsTimeOfFirstContactOnceItLeft()
    {
        // The ball's edge starts 25 mm from the wall at x = 1500 and swims on at 400 mm/s (40 mm a
        // step): the handler only pushes it out, as a fish keeps pushing.
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId ball = world.AddCircle(58f, new Vector2(1500f - 58f - 25f, 0f));
        world.HeldSubSteps = 4;
        var handler = new PushOutHandler(stop: false);

        // Step 0: not touching at the start, so the first contact is an event at its time of first
        // contact, 25 / 40 = 0.625, found by the pair's sample at the end of the step (a wall pair's
        // interval is the whole step): the sub-steps' ends up to 0.75 have passed by then, so the pair
        // keeps its own clock for the rest of the step (its later contacts are events too).
        world.SetVelocity(ball, new Vector2(400f, 0f));
        world.Step(Seconds, handler);
        Assert.False(handler.Contacts[0].Pressing);
        Assert.Equal(0.625, handler.Contacts[0].Time, 0.25 / 40.0);
        Assert.True(handler.Contacts[0].Depth <= MotionTolerances.TimeOfImpactTolerance, $"first contact {handler.Contacts[0].Depth} mm deep");
        Assert.All(handler.Contacts, c => Assert.False(c.Pressing));
        Assert.Equal(0, world.HeldAnswers);
        Assert.True(world.IsTouching(ball, walls));

        // Pressed on: each sub-step's end finds the ball 10 mm (40 / 4) into the wall and answers it there.
        for (int step = 1; step <= 3; step++)
        {
            handler.Contacts.Clear();
            world.SetVelocity(ball, new Vector2(400f, 0f));
            world.Step(Seconds, handler);
            Assert.Equal(4, handler.Contacts.Count);
            for (int k = 0; k < 4; k++)
            {
                AssertHeld(handler.Contacts[k], (k + 1) / 4.0, 10f);
            }

            Assert.Equal(4, world.HeldAnswers);
            Assert.Equal(world.Events, world.PressingEvents);
            Assert.True(world.MeasureOverlap() <= 0.5f, $"step {step}: {world.MeasureOverlap()} mm left");
        }

        // Pulled away for a step, the touch ends; pushed back at 500 mm/s across the 40 mm gap, the
        // contact is a first contact again, at 40 / 50 = 0.8 of the step (no sub-step's end).
        handler.Contacts.Clear();
        world.SetVelocity(ball, new Vector2(-400f, 0f));
        world.Step(Seconds, handler);
        Assert.Empty(handler.Contacts);
        Assert.False(world.IsTouching(ball, walls));
        float gap = 1500f - 58f - world.PositionOf(ball).X;
        Assert.Equal(40f, gap, 0.05f);
        world.SetVelocity(ball, new Vector2(500f, 0f));
        world.Step(Seconds, handler);
        Assert.False(handler.Contacts[0].Pressing);
        Assert.Equal(gap / 50.0, handler.Contacts[0].Time, 0.25 / 50.0);
        Assert.True(handler.Contacts[0].Depth <= MotionTolerances.TimeOfImpactTolerance, $"{handler.Contacts[0].Depth} mm deep");

        static void AssertHeld(in Contact c, double time, float depth)
        {
            Assert.True(c.Pressing, $"contact at {c.Time}");
            Assert.Equal(time, c.Time);
            Assert.Equal(depth, c.Depth, 0.05f);
        }
    }

    [Theory]
    [InlineData(32)]
    [InlineData(64)]
    public void ABallPressedAgainstAWallIsAnsweredAtEverySubStepHoweverManyThereAre(int subSteps)
    {
        // Held answers are not events: however many a step has, the ball is never taken for wedged (which
        // would leave its contacts to the end of the step): 40 / K mm deep at each of the K ends.
        var world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId ball = world.AddCircle(58f, new Vector2(1500f - 58f - 0.01f, 0f));
        world.HeldSubSteps = subSteps;
        var handler = new PushOutHandler(stop: false);
        world.SetVelocity(ball, new Vector2(400f, 0f));
        world.Step(Seconds, handler); // the first contact, at once: from then on the pair touches
        for (int step = 1; step <= 3; step++)
        {
            handler.Contacts.Clear();
            world.SetVelocity(ball, new Vector2(400f, 0f));
            world.Step(Seconds, handler);
            Assert.Equal(subSteps, world.HeldAnswers);
            Assert.Equal(subSteps, handler.Contacts.Count);
            Assert.All(handler.Contacts, c => Assert.Equal(40f / subSteps, c.Depth, 0.05f));
            Assert.True(world.MeasureOverlap() <= 0.5f, $"step {step}: {world.MeasureOverlap()} mm left");
        }
    }

    [Theory]
    [InlineData(2)]
    [InlineData(4)]
    public void ABallThatBouncedOffAWallMeetsItAgainAtItsTimeOfFirstContact(int subSteps)
    {
        // 25 mm from the wall at 1,500 mm/s (150 mm a step): it meets the wall at 1/6 of the step and bounces
        // straight back, ending the step 125 mm off it. The pair touches (it was answered in that step), but
        // not within the last sub-step: sent back at 1,500 mm/s, the ball meets the wall again at 125 / 150 =
        // 0.833 of the next step, found there as a first contact, not at a sub-step's end 25 mm deep.
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId ball = world.AddCircle(58f, new Vector2(1500f - 58f - 25f, 0f));
        world.HeldSubSteps = subSteps;
        var handler = new RecordingHandler(restitution: 1f);
        world.SetVelocity(ball, new Vector2(1500f, 0f));
        world.Step(Seconds, handler);
        Contact bounce = Assert.Single(handler.Contacts);
        Assert.Equal(1.0 / 6.0, bounce.Time, 0.25 / 150.0);
        Assert.True(world.IsTouching(ball, walls));
        Assert.True(world.VelocityOf(ball).X < -1400f, $"the ball did not bounce: {world.VelocityOf(ball)}");

        handler.Contacts.Clear();
        float gap = 1500f - 58f - world.PositionOf(ball).X;
        Assert.Equal(125f, gap, 0.5f);
        world.SetVelocity(ball, new Vector2(1500f, 0f));
        world.Step(Seconds, handler);
        Contact again = handler.Contacts[0];
        Assert.False(again.Pressing);
        Assert.Equal(gap / 150.0, again.Time, 0.25 / 150.0);
        Assert.True(again.Depth <= MotionTolerances.TimeOfImpactTolerance, $"{again.Depth} mm deep");
        Assert.Equal(0, world.HeldAnswers);
    }

    [Theory]
    [InlineData(4, false)]
    [InlineData(16, true)]
    public void AFastBallPressedAgainstAThinBarIsHeldOnlyWhenASubStepCannotCarryItThrough(int subSteps, bool held)
    {
        // A ball of radius 20 at 2,000 mm/s against a bar 4 mm thick: the pair's limit is (40 + 4) / 2 = 22 mm
        // and it moves 200 mm a step, so its interval is 1/16 of a step (22 / 200 = 0.11, the power of two
        // below): too short for 4 sub-steps (it keeps its own clock), just right for 16.
        var world = new MotionWorld();
        world.AddStatic(new ConvexPolygon([new Vector2(-2f, -300f), new Vector2(2f, -300f), new Vector2(2f, 300f), new Vector2(-2f, 300f)]));
        BodyId ball = world.AddCircle(20f, new Vector2(-30f, 0f));
        world.HeldSubSteps = subSteps;
        var handler = new PushOutHandler(stop: true);
        for (int step = 0; step < 10; step++)
        {
            handler.Contacts.Clear();
            world.SetVelocity(ball, new Vector2(2000f, 0f));
            world.Step(Seconds, handler);
            Assert.True(world.PositionOf(ball).X < -2f, $"step {step}: the ball went through the bar, to {world.PositionOf(ball).X}");
            Assert.True(world.MeasureOverlap() <= 0.5f, $"step {step}: {world.MeasureOverlap()} mm left");
            Assert.NotEmpty(handler.Contacts);
            if (step > 0)
            {
                Assert.All(handler.Contacts, c => Assert.Equal(held, c.Pressing));
                Assert.Equal(held, world.HeldAnswers > 0);
            }
        }
    }

    [Theory]
    [InlineData(2, 1)]
    [InlineData(4, 2)]
    [InlineData(8, 3)]
    public void RandomCrowdsWithHeldContactsEndEveryStepApart(int subSteps, int seed)
    {
        var world = Crowd(seed);
        Assert.Equal(0f, world.MeasureOverlap());
        world.HeldSubSteps = subSteps;
        var handler = new RecordingHandler(0.3f) { Record = false };
        int held = 0;
        for (int step = 0; step < 40; step++)
        {
            world.Step(Seconds, handler);
            held += world.HeldAnswers;
            Assert.True(world.LeftoverOverlap <= 0.5f, $"step {step}: {world.LeftoverOverlap} mm left");
            Assert.True(world.MeasureOverlap() <= 0.5f, $"step {step}: {world.MeasureOverlap()} mm measured");
        }

        Assert.True(held > 100, $"only {held} held answers: the crowd does not exercise held contacts");
    }

    [Fact]
    public void HeldContactsGiveTheSameStepsOnOneAndTwoThreadsAndFromRunToRun()
    {
        var reference = MotionWorldIslandTests.Run(1, out var referenceContacts, out _, heldSubSteps: 4);
        Assert.Contains(reference, line => line.Contains("held answers ", StringComparison.Ordinal) && !line.Contains("held answers 0,", StringComparison.Ordinal));
        foreach (int threads in new[] { 1, 2 })
        {
            var other = MotionWorldIslandTests.Run(threads, out var contacts, out int chunks, heldSubSteps: 4);
            Assert.Equal(threads, chunks);
            Assert.Equal(reference, other);
            Assert.Equal(referenceContacts.Count, contacts.Count);
            for (int i = 0; i < contacts.Count; i++)
            {
                Assert.True(MotionWorldIslandTests.Same(referenceContacts[i], contacts[i]), $"{threads} threads: contact {i} differs");
            }
        }

        // And the held stage changes the steps (the comparison above is not of the default model).
        var unheld = MotionWorldIslandTests.Run(1, out _, out _, heldSubSteps: 0);
        Assert.NotEqual(reference, unheld);
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(3)]
    [InlineData(4096)]
    public void SubStepsThatAreNotZeroOrAPowerOfTwoUpToTheTickLimitAreRefused(int subSteps)
    {
        var world = new MotionWorld();
        var e = Assert.Throws<ArgumentException>(() => world.HeldSubSteps = subSteps);
        Assert.Contains($"got {subSteps}", e.Message, StringComparison.Ordinal);
        Assert.Equal(0, world.HeldSubSteps);
        world.HeldSubSteps = 2048;
        Assert.Equal(2048, world.HeldSubSteps);
    }

    [Fact]
    public void SubStepsCannotChangeWhileAStepRuns()
    {
        var refusal = RefusedMidStep<ArgumentException>(w => w.HeldSubSteps = 4, out _);
        Assert.Contains("while a step runs", refusal.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AWorldThatForgetsItsTouchesPlaysWhatANewWorldPlays()
    {
        // A ball that touched the wall in the last step is put back 5 mm from it, closer than it can
        // close in a sub-step (400 mm/s: 10 mm in each of 4): still touching, the pair is held and
        // its contact answered at the first sub-step's end, 5 mm deep; forgotten, it is a first
        // contact again, at 5 / 40 = 0.125 of the step, as in a new world with the ball put there.
        var remembering = Pressed(forget: false, out BodyId ball, out BodyId walls);
        var forgetting = Pressed(forget: true, out BodyId forgettingBall, out BodyId forgettingWalls);
        Assert.True(remembering.IsTouching(ball, walls));
        Assert.False(forgetting.IsTouching(forgettingBall, forgettingWalls));
        Assert.Equal(0, forgetting.TouchingPairs);

        var fresh = new MotionWorld();
        fresh.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId freshBall = fresh.AddCircle(58f, new Vector2(1500f - 58f - 5f, 0f));
        fresh.HeldSubSteps = 4;

        var held = StepOn(remembering, ball);
        var forgotten = StepOn(forgetting, forgettingBall);
        var anew = StepOn(fresh, freshBall);
        Assert.True(held[0].Pressing && held[0].Time == 0.25, $"remembered: first answer at {held[0].Time}, pressing {held[0].Pressing}");
        Assert.False(forgotten[0].Pressing);
        Assert.Equal(0.125, forgotten[0].Time, 0.25 / 40.0);
        Assert.Equal(anew.Select(c => (c.Time, c.Depth, c.Pressing)), forgotten.Select(c => (c.Time, c.Depth, c.Pressing)));

        static MotionWorld Pressed(bool forget, out BodyId ball, out BodyId walls)
        {
            var world = new MotionWorld();
            walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
            ball = world.AddCircle(58f, new Vector2(1500f - 58f - 25f, 0f));
            world.HeldSubSteps = 4;
            world.SetVelocity(ball, new Vector2(400f, 0f));
            world.Step(Seconds, new PushOutHandler(stop: false));
            Assert.True(world.IsTouching(ball, walls));
            world.SetPose(ball, new Vector2(1500f - 58f - 5f, 0f), 0f);
            if (forget)
            {
                world.ForgetTouches();
            }

            return world;
        }

        static List<Contact> StepOn(MotionWorld world, BodyId ball)
        {
            var handler = new PushOutHandler(stop: false);
            world.SetVelocity(ball, new Vector2(400f, 0f));
            world.Step(Seconds, handler);
            Assert.NotEmpty(handler.Contacts);
            return handler.Contacts;
        }
    }

    [Fact]
    public void TouchesCannotBeForgottenWhileAStepRuns()
    {
        var refusal = RefusedMidStep<InvalidOperationException>(w => w.ForgetTouches(), out MotionWorld world);
        Assert.Contains("while a step or Settle runs", refusal.Message, StringComparison.Ordinal);
        Assert.Equal(1, world.TouchingPairs);
    }

    // A ball driven into the wall; at its contact the handler tries the change and must be refused.
    private static TException RefusedMidStep<TException>(Action<MotionWorld> change, out MotionWorld world)
        where TException : Exception
    {
        world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId ball = world.AddCircle(58f, new Vector2(1400f, 0f));
        world.SetVelocity(ball, new Vector2(1000f, 0f));
        TException? refusal = null;
        var handler = new PushOutHandler { Probe = w => refusal ??= Assert.Throws<TException>(() => change(w)) };
        world.Step(Seconds, handler);
        Assert.NotNull(refusal);
        return refusal!;
    }

    // About 460 bodies apart on a jittered lattice in a pool of 10 × 6 m: fish swimming at 300 mm/s
    // (turning), balls at up to 2,000 mm/s, squares, a few round obstacles.
    private static MotionWorld Crowd(int seed)
    {
        var random = new Random(seed);
        var world = new MotionWorld();
        var field = new Field(10000f, 6000f);
        world.AddWalls(field);
        foreach (Aabb block in field.GoalBlocks)
        {
            world.AddStatic(block);
        }

        var square = new ConvexPolygon([new Vector2(-30f, -20f), new Vector2(30f, -20f), new Vector2(30f, 20f), new Vector2(-30f, 20f)]);
        for (int column = 0; column < 18; column++)
        {
            for (int row = 0; row < 22; row++)
            {
                Vector2 at = new(-4500f + (column * 500f) + 250f, -2860f + (row * 260f) + 130f);
                at += new Vector2((float)(random.NextDouble() - 0.5) * 20f, (float)(random.NextDouble() - 0.5) * 20f);
                double kind = random.NextDouble();
                Vector2 velocity = new((float)(random.NextDouble() - 0.5) * 4000f, (float)(random.NextDouble() - 0.5) * 4000f);
                if (kind < 0.4)
                {
                    float heading = (float)((random.NextDouble() - 0.5) * 0.3);
                    BodyId fish = world.AddFish(FishSize.Default, new FishPose(at, heading, 0.1f, -0.1f, 0.2f));
                    world.SetVelocity(fish, 300f * new Vector2(MathF.Cos(heading), MathF.Sin(heading)), (float)(random.NextDouble() - 0.5));
                }
                else if (kind < 0.8)
                {
                    BodyId ball = world.AddCircle(58f, at);
                    world.SetVelocity(ball, velocity * 0.5f);
                }
                else if (kind < 0.95)
                {
                    BodyId polygon = world.AddPolygon(square, at, (float)(random.NextDouble() * Math.PI));
                    world.SetVelocity(polygon, velocity * 0.2f, 1f);
                }
                else
                {
                    world.AddStatic(new Circle(at, 60f));
                }
            }
        }

        return world;
    }
}
