namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// Contacts that persist: a pair touches from its first answer until a whole step passes without
/// one (<see cref="IContactHandler.OnTouchBegan"/>, <see cref="IContactHandler.OnTouchEnded"/>,
/// <see cref="MotionWorld.IsTouching"/>), and, with <see cref="MotionWorld.PressingContacts"/>
/// on, a pair that touches is pressing: its contacts after the first are answered where a sample
/// finds them, on the sampling grid, rather than at a time of first contact searched between two
/// samples.
/// </summary>
public sealed class MotionWorldTouchTests
{
    [Fact]
    public void ABallPressedAgainstAWallTouchesOnceAndItsLaterContactsArePressing()
    {
        var (world, ball, walls) = BallBesideTheRightWall();
        world.PressingContacts = true;
        var handler = new PushOutHandler();
        for (int step = 0; step < 6; step++)
        {
            handler.Contacts.Clear();
            world.SetVelocity(ball, new Vector2(400f, 0f));
            world.Step(0.1f, handler);
            Assert.True(world.Events > 0, $"step {step}: the ball should meet the wall");
            Assert.True(world.IsTouching(ball, walls), $"step {step}");
            Assert.Equal(1, world.TouchingPairs);
            if (step == 0)
            {
                // The first contact is found at its time of first contact, between two samples.
                Assert.Equal(0, world.PressingEvents);
                Assert.True(handler.Contacts[0].Depth <= MotionTolerances.TimeOfImpactTolerance, $"first contact {handler.Contacts[0].Depth} mm deep");
                Assert.False(OnSampleGrid(handler.Contacts[0].Time), $"first contact at {handler.Contacts[0].Time}");
            }
            else
            {
                // Every later contact is pressing: answered where a sample found it.
                Assert.Equal(world.Events, world.PressingEvents);
                Assert.All(handler.Contacts, c => Assert.True(c.Pressing && OnSampleGrid(c.Time), $"step {step}: pressing {c.Pressing} contact at {c.Time}"));
            }

            Assert.True(world.MeasureOverlap() <= 1f, $"step {step}: {world.MeasureOverlap()} mm left");
        }

        Assert.Equal([(ball, walls)], handler.Began);
        Assert.Empty(handler.Ended);

        // Pulled away: the first step without an answer ends the touch, once.
        world.SetVelocity(ball, new Vector2(-400f, 0f));
        world.Step(0.1f, handler);
        Assert.Equal(0, world.Events);
        Assert.False(world.IsTouching(ball, walls));
        Assert.Equal(0, world.TouchingPairs);
        Assert.Equal([(ball, walls)], handler.Ended);
        world.Step(0.1f, handler);
        Assert.Single(handler.Ended);
    }

    [Fact]
    public void WithPressingContactsOffEveryContactIsFoundAtItsTimeOfFirstContact()
    {
        var (world, ball, walls) = BallBesideTheRightWall();
        Assert.False(world.PressingContacts); // the default
        var handler = new PushOutHandler();
        for (int step = 0; step < 6; step++)
        {
            handler.Contacts.Clear();
            world.SetVelocity(ball, new Vector2(400f, 0f));
            world.Step(0.1f, handler);
            Assert.True(world.Events > 0);
            Assert.Equal(0, world.PressingEvents);
            Assert.All(handler.Contacts, c => Assert.True(!c.Pressing && c.Depth <= MotionTolerances.TimeOfImpactTolerance, $"step {step}: contact {c.Depth} mm deep"));
            Assert.True(world.IsTouching(ball, walls));
        }

        // The touch is the same with or without pressing contacts: it begins once.
        Assert.Equal([(ball, walls)], handler.Began);
    }

    [Fact]
    public void AFishPushingABallAcrossThePoolTouchesItOnceAndLeavesNoOverlap()
    {
        // A fish swims straight into a ball and pushes it: a pair pressed cycle after cycle.
        var world = new MotionWorld();
        world.AddWalls(new Field(4000f, 2000f, goalBlocks: false));
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(new Vector2(-1200f, 0f), 0f, 0f, 0f, 0f));
        BodyId ball = world.AddCircle(58f, new Vector2(-850f, 0f));
        world.PressingContacts = true;
        var handler = new PushingHandler();
        int pressing = 0;
        for (int step = 0; step < 20; step++)
        {
            world.SetVelocity(fish, new Vector2(500f, 0f), 0f);
            world.SetVelocity(ball, world.VelocityOf(ball) * 0.5f); // water drag: the fish catches up every step
            world.Step(0.1f, handler);
            pressing += world.PressingEvents;
            Assert.True(world.MeasureOverlap() <= 1f, $"step {step}: {world.MeasureOverlap()} mm left");
        }

        Assert.True(world.IsTouching(fish, ball));
        Assert.Equal(1, handler.Began.Count(p => p == (fish, ball)));
        Assert.True(pressing > 10, $"{pressing} pressing events in 20 pushed steps");
        Assert.True(world.PositionOf(ball).X > -150f, $"the ball was pushed to {world.PositionOf(ball)}, from x = -850");
    }

    [Fact]
    public void ClearForgetsEveryTouchWithoutEndingIt()
    {
        var (world, ball, walls) = BallBesideTheRightWall();
        var handler = new PushOutHandler();
        world.SetVelocity(ball, new Vector2(400f, 0f));
        world.Step(0.1f, handler);
        Assert.True(world.IsTouching(ball, walls));
        world.Clear();
        Assert.Equal(0, world.TouchingPairs);
        BodyId again = world.AddCircle(58f, new Vector2(0f, 0f));
        world.Step(0.1f, handler);
        world.Step(0.1f, handler);
        Assert.Empty(handler.Ended);
        Assert.False(world.IsTouching(again, again));
        Assert.Throws<ArgumentException>(() => world.IsTouching(ball, again));
    }

    [Fact]
    public void PressingContactsCannotBeSwitchedDuringAStep()
    {
        var (world, ball, _) = BallBesideTheRightWall();
        var handler = new SwitchingHandler();
        world.SetVelocity(ball, new Vector2(400f, 0f));
        world.Step(0.1f, handler);
        Assert.NotNull(handler.Refused);
        Assert.Equal("value", handler.Refused!.ParamName);
        Assert.False(world.PressingContacts);
    }

    private static bool OnSampleGrid(double time)
    {
        double ticks = time * 2048.0;
        return ticks == Math.Floor(ticks);
    }

    private static (MotionWorld World, BodyId Ball, BodyId Walls) BallBesideTheRightWall()
    {
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId ball = world.AddCircle(58f, new Vector2(1500f - 58f - 25f, 0f));
        return (world, ball, walls);
    }

    // A fish pushes a ball: the ball is moved out of the fish and takes the fish's velocity.
    private sealed class PushingHandler : IContactHandler
    {
        public List<(BodyId, BodyId)> Began { get; } = [];

        public void OnTouchBegan(MotionWorld world, BodyId bodyA, BodyId bodyB) => Began.Add((bodyA, bodyB));

        public void OnContact(MotionWorld world, in Contact contact)
        {
            BodyId a = contact.BodyA, b = contact.BodyB;
            Vector2 push = contact.Mtv + (contact.Normal * 0.01f);
            if (world.KindOf(b) == BodyKind.Circle)
            {
                world.SetPose(b, world.PositionOf(b) - push, 0f);
                world.SetVelocity(b, world.VelocityOf(a));
            }
            else if (world.KindOf(a) == BodyKind.Circle)
            {
                world.SetPose(a, world.PositionOf(a) + push, 0f);
                world.SetVelocity(a, Vector2.Zero);
            }
            else
            {
                world.SetPose(a, world.PositionOf(a) + push, world.HeadingOf(a));
                world.SetVelocity(a, Vector2.Zero, 0f);
            }
        }

        public void OnMoveRejected(MotionWorld world, BodyId body)
        {
        }
    }

    private sealed class SwitchingHandler : IContactHandler
    {
        public ArgumentException? Refused { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            try
            {
                world.PressingContacts = true;
            }
            catch (ArgumentException e)
            {
                Refused = e;
            }

            world.SetPose(contact.BodyA, world.PositionOf(contact.BodyA) + contact.Mtv + (contact.Normal * 0.01f), 0f);
            world.SetVelocity(contact.BodyA, Vector2.Zero);
        }

        public void OnMoveRejected(MotionWorld world, BodyId body)
        {
        }
    }
}
