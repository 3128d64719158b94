using System;
using System.Collections.Generic;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Pool;
using Xunit;

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
        int fish = stepper.AddFish(FishSize.Default, start);

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
        int a = stepper.AddCircle(50f, new Vector2(0f, 0f));
        int b = stepper.AddCircle(50f, new Vector2(400f, 0f));
        stepper.SetVelocity(a, new Vector2(1000f, 0f));
        stepper.Step(0.1f, new RejectOnContact(-1));
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
        int ball = stepper.AddCircle(50f, Vector2.Zero);
        int walls = stepper.AddWalls(new Field(3000f, 2000f, goalBlocks: false));

        var outside = Assert.Throws<ArgumentException>(() => stepper.RejectMove(ball));
        Assert.Equal("body", outside.ParamName);
        Assert.Contains("only from a handler", outside.Message, StringComparison.Ordinal);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.RejectMove(walls)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.RejectMove(7)).ParamName);
    }

    // Rejects the move of one body at its first contact (none when the body is −1); records what the stepper reports.
    private sealed class RejectOnContact(int body) : IContactHandler
    {
        public List<int> Rejected { get; } = [];

        public double ContactTime { get; private set; } = -1.0;

        public void OnContact(Stepper stepper, in Contact contact)
        {
            if (body >= 0 && (contact.BodyA == body || contact.BodyB == body) && Rejected.Count == 0)
            {
                ContactTime = contact.Time;
                stepper.RejectMove(body);
            }
        }

        public void OnMoveRejected(Stepper stepper, int rejected) => Rejected.Add(rejected);
    }
}
