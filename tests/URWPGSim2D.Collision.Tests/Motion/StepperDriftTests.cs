namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>A body's drift: it moves the body with its velocity, it is not its velocity, and a rejected move clears it.</summary>
public sealed class StepperDriftTests
{
    [Fact]
    public void ABallMovesWithItsVelocityPlusItsDrift()
    {
        var stepper = new Stepper();
        BodyId ball = stepper.AddCircle(50f, new Vector2(0f, 0f));
        stepper.SetVelocity(ball, new Vector2(1000f, 0f));
        stepper.SetDrift(ball, new Vector2(0f, 500f), angularDrift: 3f);
        stepper.Step(0.1f, new RecordingHandler());

        // 0.1 s at (1000, 500) mm/s; the velocity read back is the ball's own, the drift its own too.
        Assert.Equal(100f, stepper.PositionOf(ball).X, 1e-3f);
        Assert.Equal(50f, stepper.PositionOf(ball).Y, 1e-3f);
        Assert.Equal(new Vector2(1000f, 0f), stepper.VelocityOf(ball));
        Assert.Equal(new Vector2(0f, 500f), stepper.DriftOf(ball));
        Assert.Equal(0f, stepper.AngularDriftOf(ball)); // a circle does not turn
    }

    [Fact]
    public void AFishTurnsWithItsAngularVelocityPlusItsTurningDrift()
    {
        var stepper = new Stepper();
        BodyId fish = stepper.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f));
        stepper.SetVelocity(fish, Vector2.Zero, 1f);
        stepper.SetDrift(fish, Vector2.Zero, 0.5f);
        stepper.Step(0.1f, new RecordingHandler());

        Assert.Equal(0.15f, stepper.HeadingOf(fish), 1e-5f);
        Assert.Equal(1f, stepper.AngularVelocityOf(fish));
        Assert.Equal(0.5f, stepper.AngularDriftOf(fish));
    }

    [Fact]
    public void ARejectedMoveStopsTheBodyAndClearsItsDrift()
    {
        // A bar 200 × 40 mm turning between two boxes 150 mm apart jams; settling cannot free it, so
        // a step's move is rejected (see StepperWedgeTests). Its turn is half velocity, half drift.
        var stepper = StepperWedgeTests.BarInSlot(out BodyId body);
        var handler = new RecordingHandler { Record = false };
        int rejected = 0;
        for (int step = 0; step < 30 && rejected == 0; step++)
        {
            stepper.SetVelocity(body, Vector2.Zero, 1.5f);
            stepper.SetDrift(body, Vector2.Zero, 1.5f);
            stepper.Step(0.1f, handler);
            rejected = stepper.RejectedMoves;
        }

        Assert.True(rejected > 0, "no move was rejected");
        Assert.Equal(0f, stepper.AngularVelocityOf(body));
        Assert.Equal(0f, stepper.AngularDriftOf(body));
        Assert.Equal(Vector2.Zero, stepper.DriftOf(body));
    }

    [Fact]
    public void ADriftThatIsNotFiniteIsRefused()
    {
        var stepper = new Stepper();
        BodyId ball = stepper.AddCircle(50f, Vector2.Zero);
        Assert.Contains("drift", Assert.Throws<System.ArgumentException>(() => stepper.SetDrift(ball, new Vector2(float.NaN, 0f))).Message);
    }
}
