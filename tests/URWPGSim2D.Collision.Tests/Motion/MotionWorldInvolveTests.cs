namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary><see cref="MotionWorld.Involve"/>: a body counts as changed by a response, and nothing of it changes.</summary>
public sealed class MotionWorldInvolveTests
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
        var world = new MotionWorld();
        BodyId ball = world.AddCircle(50f, new Vector2(10f, 20f));
        world.SetVelocity(ball, new Vector2(300f, -40f));
        world.SetDrift(ball, new Vector2(5f, 6f));
        world.Involve(ball);

        Assert.Equal(new Vector2(10f, 20f), world.PositionOf(ball));
        Assert.Equal(new Vector2(300f, -40f), world.VelocityOf(ball));
        Assert.Equal(new Vector2(5f, 6f), world.DriftOf(ball));
        world.Step(0.1f, new RecordingHandler());
        Assert.True(Vector2.Distance(new Vector2(10f + 30.5f, 20f - 3.4f), world.PositionOf(ball)) < 1e-4f, $"ended at {world.PositionOf(ball)}");
    }

    [Fact]
    public void AStaticBodyOrAMissingOneIsRefusedByName()
    {
        var world = new MotionWorld();
        BodyId wall = world.AddStatic(new URWPGSim2D.Collision.Shapes.Circle(Vector2.Zero, 10f));
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.Involve(wall)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.Involve(default)).ParamName);
        BodyId elsewhere = new MotionWorld().AddCircle(10f, Vector2.Zero);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.Involve(elsewhere)).ParamName);
    }

    private static (Vector2[] Positions, int Contacts) Run(bool involve)
    {
        var world = new MotionWorld();
        BodyId a = world.AddCircle(50f, new Vector2(0f, 0f));
        BodyId b = world.AddCircle(50f, new Vector2(300f, 0f));
        BodyId c = world.AddCircle(50f, new Vector2(-1000f, 600f));
        world.SetVelocity(a, new Vector2(3000f, 0f));
        world.SetVelocity(c, new Vector2(800f, -400f));
        var handler = new InvolvingHandler(involve ? [c, b, a] : []);
        world.Step(0.1f, handler);
        return ([world.PositionOf(a), world.PositionOf(b), world.PositionOf(c)], handler.Inner.Contacts.Count);
    }

    // Involves the given bodies, then responds as the recording handler does.
    private sealed class InvolvingHandler(BodyId[] involve) : IContactHandler
    {
        public RecordingHandler Inner { get; } = new(restitution: 1f);

        public void OnContact(MotionWorld world, in Contact contact)
        {
            foreach (BodyId body in involve)
            {
                world.Involve(body);
            }

            Inner.OnContact(world, contact);
        }

        public void OnMoveRejected(MotionWorld world, BodyId body) => Inner.OnMoveRejected(world, body);
    }
}
