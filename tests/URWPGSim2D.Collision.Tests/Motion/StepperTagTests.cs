namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary><see cref="Stepper.SetTag"/> and <see cref="Stepper.TagOf"/>: the caller's number for each body, kept and never read.</summary>
public sealed class StepperTagTests
{
    [Fact]
    public void EveryKindOfBodyKeepsItsTagAndContactsCarryTheTaggedBodies()
    {
        var stepper = new Stepper();
        BodyId walls = stepper.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId block = stepper.AddStatic(new URWPGSim2D.Collision.Shapes.Circle(new Vector2(400f, 0f), 60f));
        BodyId fish = stepper.AddFish(FishSize.Default, new FishPose(new Vector2(-400f, 0f), 0f, 0f, 0f, 0f));
        BodyId ball = stepper.AddCircle(58f, new Vector2(0f, 0f));
        Assert.Equal(0, stepper.TagOf(ball));

        // Tags unrelated to the ids, set before and between steps.
        var tags = new Dictionary<BodyId, int> { [walls] = -7, [block] = 1 << 30, [fish] = 12345, [ball] = int.MinValue };
        foreach ((BodyId body, int tag) in tags)
        {
            stepper.SetTag(body, tag);
        }

        stepper.SetVelocity(ball, new Vector2(6000f, 0f));
        stepper.SetVelocity(fish, new Vector2(-3000f, 0f));
        var handler = new TagRecorder();
        for (int step = 0; step < 10; step++)
        {
            stepper.Step(0.1f, handler);
        }

        Assert.True(handler.Seen.Count >= 2, "too few contacts: the scene does not test the tags");
        foreach ((BodyId body, int tag) in handler.Seen)
        {
            Assert.Equal(tags[body], tag);
        }

        foreach ((BodyId body, int tag) in tags)
        {
            Assert.Equal(tag, stepper.TagOf(body));
        }
    }

    [Fact]
    public void ABodyThatDoesNotExistIsRefusedByName()
    {
        var stepper = new Stepper();
        stepper.AddCircle(10f, Vector2.Zero);
        var other = new Stepper();
        other.AddCircle(10f, Vector2.Zero);
        BodyId elsewhere = other.AddCircle(10f, Vector2.Zero);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.TagOf(elsewhere)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.SetTag(default, 3)).ParamName);
    }

    // Records the tag of each contact's bodies as the handler sees them, and bounces the bodies apart.
    private sealed class TagRecorder : IContactHandler
    {
        private readonly RecordingHandler _inner = new(restitution: 1f);

        public List<(BodyId Body, int Tag)> Seen { get; } = [];

        public void OnContact(Stepper stepper, in Contact contact)
        {
            Seen.Add((contact.BodyA, stepper.TagOf(contact.BodyA)));
            Seen.Add((contact.BodyB, stepper.TagOf(contact.BodyB)));
            _inner.OnContact(stepper, contact);
        }

        public void OnMoveRejected(Stepper stepper, BodyId body) => _inner.OnMoveRejected(stepper, body);
    }
}
