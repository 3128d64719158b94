namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary><see cref="Stepper.Involve"/>: a body counts as changed by a response, and nothing of it changes.</summary>
public sealed class StepperInvolveTests
{
    [Fact]
    public void InvolvingBodiesInAResponseChangesNoMotion()
    {
        // Ball a runs into ball b at rest; c flies freely far away. One run's response involves c,
        // b and a (in that order) before responding as usual, the other's does not: every body ends
        // where it ends without involving (to rounding of the re-based motion), and c where free
        // flight puts it.
        (Vector2[] plain, int plainContacts) = Run(involve: false);
        (Vector2[] involved, int involvedContacts) = Run(involve: true);

        Assert.True(plainContacts > 0, "the balls did not meet: the scene does not test a response");
        Assert.Equal(plainContacts, involvedContacts);
        for (int i = 0; i < plain.Length; i++)
        {
            Assert.True(Vector2.Distance(plain[i], involved[i]) < 1e-3f, $"body {i}: {plain[i]} without involving, {involved[i]} with");
        }

        Assert.True(Vector2.Distance(new Vector2(-1000f + 80f, 600f - 40f), involved[2]) < 1e-3f, $"c ended at {involved[2]}");
    }

    [Fact]
    public void BetweenStepsInvolvingChangesNothing()
    {
        var stepper = new Stepper();
        BodyId ball = stepper.AddCircle(50f, new Vector2(10f, 20f));
        stepper.SetVelocity(ball, new Vector2(300f, -40f));
        stepper.SetDrift(ball, new Vector2(5f, 6f));
        stepper.Involve(ball);

        Assert.Equal(new Vector2(10f, 20f), stepper.PositionOf(ball));
        Assert.Equal(new Vector2(300f, -40f), stepper.VelocityOf(ball));
        Assert.Equal(new Vector2(5f, 6f), stepper.DriftOf(ball));
        stepper.Step(0.1f, new RecordingHandler());
        Assert.True(Vector2.Distance(new Vector2(10f + 30.5f, 20f - 3.4f), stepper.PositionOf(ball)) < 1e-4f, $"ended at {stepper.PositionOf(ball)}");
    }

    [Fact]
    public void AStaticBodyOrAMissingOneIsRefusedByName()
    {
        var stepper = new Stepper();
        BodyId wall = stepper.AddStatic(new URWPGSim2D.Collision.Shapes.Circle(Vector2.Zero, 10f));
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.Involve(wall)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.Involve(default)).ParamName);
        BodyId elsewhere = new Stepper().AddCircle(10f, Vector2.Zero);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.Involve(elsewhere)).ParamName);
    }

    private static (Vector2[] Positions, int Contacts) Run(bool involve)
    {
        var stepper = new Stepper();
        BodyId a = stepper.AddCircle(50f, new Vector2(0f, 0f));
        BodyId b = stepper.AddCircle(50f, new Vector2(300f, 0f));
        BodyId c = stepper.AddCircle(50f, new Vector2(-1000f, 600f));
        stepper.SetVelocity(a, new Vector2(3000f, 0f));
        stepper.SetVelocity(c, new Vector2(800f, -400f));
        var handler = new InvolvingHandler(involve ? [c, b, a] : []);
        stepper.Step(0.1f, handler);
        return ([stepper.PositionOf(a), stepper.PositionOf(b), stepper.PositionOf(c)], handler.Inner.Contacts.Count);
    }

    // Involves the given bodies, then responds as the recording handler does.
    private sealed class InvolvingHandler(BodyId[] involve) : IContactHandler
    {
        public RecordingHandler Inner { get; } = new(restitution: 1f);

        public void OnContact(Stepper stepper, in Contact contact)
        {
            foreach (BodyId body in involve)
            {
                stepper.Involve(body);
            }

            Inner.OnContact(stepper, contact);
        }

        public void OnMoveRejected(Stepper stepper, BodyId body) => Inner.OnMoveRejected(stepper, body);
    }
}
