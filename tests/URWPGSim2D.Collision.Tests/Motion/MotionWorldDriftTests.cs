namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>A body's drift: it moves the body with its velocity, it is not its velocity, and a rejected move clears it.</summary>
public sealed class MotionWorldDriftTests
{
    [Fact]
    public void ABallMovesWithItsVelocityPlusItsDrift()
    {
        var world = new MotionWorld();
        BodyId ball = world.AddCircle(50f, new Vector2(0f, 0f));
        world.SetVelocity(ball, new Vector2(1000f, 0f));
        world.SetDrift(ball, new Vector2(0f, 500f), angularDrift: 3f);
        world.Step(0.1f, new RecordingHandler());

        // 0.1 s at (1000, 500) mm/s; the velocity read back is the ball's own, the drift its own too.
        Assert.Equal(100f, world.PositionOf(ball).X, 1e-3f);
        Assert.Equal(50f, world.PositionOf(ball).Y, 1e-3f);
        Assert.Equal(new Vector2(1000f, 0f), world.VelocityOf(ball));
        Assert.Equal(new Vector2(0f, 500f), world.DriftOf(ball));
        Assert.Equal(0f, world.AngularDriftOf(ball)); // a circle does not turn
    }

    [Fact]
    public void AFishTurnsWithItsAngularVelocityPlusItsTurningDrift()
    {
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f));
        world.SetVelocity(fish, Vector2.Zero, 1f);
        world.SetDrift(fish, Vector2.Zero, 0.5f);
        world.Step(0.1f, new RecordingHandler());

        Assert.Equal(0.15f, world.HeadingOf(fish), 1e-5f);
        Assert.Equal(1f, world.AngularVelocityOf(fish));
        Assert.Equal(0.5f, world.AngularDriftOf(fish));
    }

    [Fact]
    public void ARejectedMoveStopsTheBodyAndClearsItsDrift()
    {
        // A bar 200 × 40 mm turning between two boxes 150 mm apart jams; settling cannot free it, so
        // a step's move is rejected (see MotionWorldWedgeTests). Its turn is half velocity, half drift.
        var world = MotionWorldWedgeTests.BarInSlot(out BodyId body);
        var handler = new RecordingHandler { Record = false };
        int rejected = 0;
        for (int step = 0; step < 30 && rejected == 0; step++)
        {
            world.SetVelocity(body, Vector2.Zero, 1.5f);
            world.SetDrift(body, Vector2.Zero, 1.5f);
            world.Step(0.1f, handler);
            rejected = world.RejectedMoves;
        }

        Assert.True(rejected > 0, "no move was rejected");
        Assert.Equal(0f, world.AngularVelocityOf(body));
        Assert.Equal(0f, world.AngularDriftOf(body));
        Assert.Equal(Vector2.Zero, world.DriftOf(body));
    }

    [Fact]
    public void ADriftThatIsNotFiniteIsRefused()
    {
        var world = new MotionWorld();
        BodyId ball = world.AddCircle(50f, Vector2.Zero);
        Assert.Contains("drift", Assert.Throws<System.ArgumentException>(() => world.SetDrift(ball, new Vector2(float.NaN, 0f))).Message);
    }
}
