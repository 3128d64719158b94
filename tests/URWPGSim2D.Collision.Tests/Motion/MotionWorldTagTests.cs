namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary><see cref="MotionWorld.SetTag"/> and <see cref="MotionWorld.TagOf"/>: the caller's number for each body, kept and never read.</summary>
public sealed class MotionWorldTagTests
{
    [Fact]
    public void EveryKindOfBodyKeepsItsTagAndContactsCarryTheTaggedBodies()
    {
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyId block = world.AddStatic(new URWPGSim2D.Collision.Shapes.Circle(new Vector2(400f, 0f), 60f));
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(new Vector2(-400f, 0f), 0f, 0f, 0f, 0f));
        BodyId ball = world.AddCircle(58f, new Vector2(0f, 0f));
        Assert.Equal(0, world.TagOf(ball));

        // Tags unrelated to the ids, set before and between steps.
        var tags = new Dictionary<BodyId, int> { [walls] = -7, [block] = 1 << 30, [fish] = 12345, [ball] = int.MinValue };
        foreach ((BodyId body, int tag) in tags)
        {
            world.SetTag(body, tag);
        }

        world.SetVelocity(ball, new Vector2(6000f, 0f));
        world.SetVelocity(fish, new Vector2(-3000f, 0f));
        var handler = new TagRecorder();
        for (int step = 0; step < 10; step++)
        {
            world.Step(0.1f, handler);
        }

        Assert.True(handler.Seen.Count >= 2, "too few contacts: the scene does not test the tags");
        foreach ((BodyId body, int tag) in handler.Seen)
        {
            Assert.Equal(tags[body], tag);
        }

        foreach ((BodyId body, int tag) in tags)
        {
            Assert.Equal(tag, world.TagOf(body));
        }
    }

    [Fact]
    public void ABodyThatDoesNotExistIsRefusedByName()
    {
        var world = new MotionWorld();
        world.AddCircle(10f, Vector2.Zero);
        var other = new MotionWorld();
        other.AddCircle(10f, Vector2.Zero);
        BodyId elsewhere = other.AddCircle(10f, Vector2.Zero);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.TagOf(elsewhere)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.SetTag(default, 3)).ParamName);
    }

    // Records the tag of each contact's bodies as the handler sees them, and bounces the bodies apart.
    private sealed class TagRecorder : IContactHandler
    {
        private readonly RecordingHandler _inner = new(restitution: 1f);

        public List<(BodyId Body, int Tag)> Seen { get; } = [];

        public void OnContact(MotionWorld world, in Contact contact)
        {
            Seen.Add((contact.BodyA, world.TagOf(contact.BodyA)));
            Seen.Add((contact.BodyB, world.TagOf(contact.BodyB)));
            _inner.OnContact(world, contact);
        }

        public void OnMoveRejected(MotionWorld world, BodyId body) => _inner.OnMoveRejected(world, body);
    }
}
