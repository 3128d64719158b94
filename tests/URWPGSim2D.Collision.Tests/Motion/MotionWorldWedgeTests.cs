namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// A body that cannot be separated (a wedge: every response pushes it into the other obstacle)
/// costs a bounded number of events per step and still ends every step within the guarantee: once
/// it has had <see cref="WedgePolicy.EventsBeforeDeferring"/> events in a step, its further
/// contacts that cannot tunnel before the step ends are left to the end of the step, and if settling
/// there does not free it, its move is rejected (it stays where the last step ended, which was
/// free). (Without that the bar below takes 65 events a step.) The same holds with held contacts
/// on 2, 4 and 8 sub-steps.
/// </summary>
public sealed class MotionWorldWedgeTests
{
    [Theory]
    [InlineData(0)]
    [InlineData(2)]
    [InlineData(4)]
    [InlineData(8)]
    public void ABarSpinningInASlotTooNarrowForItEndsEveryStepWithinTheGuarantee(int heldSubSteps)
    {
        // A bar 200 × 40 mm turning at 3 rad/s between two boxes 150 mm apart: once it jams, pushing
        // one end out of one box pushes the other end into the other one, and it keeps turning.
        var world = BarInSlot(out BodyId body);
        world.HeldSubSteps = heldSubSteps;
        var handler = new RecordingHandler { Record = false };
        int most = 0, rejected = 0, held = 0;
        for (int step = 0; step < 30; step++)
        {
            world.SetVelocity(body, Vector2.Zero, 3f);
            world.Step(0.1f, handler);
            most = Math.Max(most, world.Events);
            held += world.HeldAnswers;
            Assert.True(world.LeftoverOverlap <= MotionTolerances.ContactSlop, $"step {step}: {world.LeftoverOverlap} mm left");
            rejected += world.RejectedMoves;
            Assert.True(world.MeasureOverlap() <= 0.5f, $"step {step}: measured {world.MeasureOverlap()} mm");
        }

        // Jammed (it turned from π/2 until both ends met the boxes, about 0.6 rad), and without the
        // deferral it would take the 64 events a body may have before contacts are handled where found.
        Assert.InRange(world.HeadingOf(body), 2.0f, 2.3f);
        Assert.True(most <= new WedgePolicy().EventsBeforeDeferring + 2, $"{most} events in one step");

        // A jammed step whose overlap settling cannot remove goes back to where the last one ended.
        Assert.True(rejected > 0, "no move was rejected");

        // With held contacts the jammed bar is also answered at every sub-step's end where it presses
        // (those answers are not events): the same guarantee, the same rejected moves.
        Assert.Equal(heldSubSteps > 0, held > 0);
    }

    /// <summary>A bar 200 × 40 mm standing (heading π/2) between two boxes 150 mm apart, in a pool.</summary>
    internal static MotionWorld BarInSlot(out BodyId bar)
    {
        var world = new MotionWorld();
        world.AddWalls(new Field());
        world.AddStatic(new Aabb(new Vector2(-400f, -300f), new Vector2(-75f, 300f)));
        world.AddStatic(new Aabb(new Vector2(75f, -300f), new Vector2(400f, 300f)));
        var shape = new ConvexPolygon([new Vector2(-100f, -20f), new Vector2(100f, -20f), new Vector2(100f, 20f), new Vector2(-100f, 20f)]);
        bar = world.AddPolygon(shape, Vector2.Zero, MathF.PI / 2f);
        return world;
    }
}
