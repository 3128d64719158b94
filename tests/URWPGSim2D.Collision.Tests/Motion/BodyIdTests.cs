namespace URWPGSim2D.Collision.Tests.Motion;

public sealed class BodyIdTests
{
    [Fact]
    public void IdsNumberTheBodiesInTheOrderAddedAndTellTheStaticOnes()
    {
        var world = new MotionWorld();
        BodyId[] ids =
        [
            world.AddStatic(new Circle(new Vector2(500f, 0f), 40f)),
            world.AddFish(FishSize.Default, new FishPose(new Vector2(-400f, 0f), 0f, 0f, 0f, 0f)),
            world.AddWalls(new Field(3000f, 2000f, goalBlocks: false)),
            world.AddCircle(58f, new Vector2(0f, 300f)),
            world.AddPolygon(new ConvexPolygon([new Vector2(-20f, -10f), new Vector2(20f, -10f), new Vector2(0f, 15f)]), new Vector2(0f, -300f), 0.5f),
        ];
        bool[] isStatic = [true, false, true, false, false];
        BodyKind[] kinds = [BodyKind.Static, BodyKind.Fish, BodyKind.Walls, BodyKind.Circle, BodyKind.Polygon];
        for (int i = 0; i < ids.Length; i++)
        {
            Assert.Equal(i, ids[i].Index);
            Assert.Equal(isStatic[i], ids[i].IsStatic);
            Assert.False(ids[i].IsNull);
            Assert.Equal(kinds[i], world.KindOf(ids[i]));
            Assert.Equal((isStatic[i] ? "static body " : "body ") + i, ids[i].ToString());
        }

        Assert.Equal(ids.Length, new HashSet<BodyId>(ids).Count);
    }

    [Fact]
    public void AnIdEqualsItselfOnlyNotTheSameIndexOfAnotherMotionWorld()
    {
        var one = new MotionWorld();
        var two = new MotionWorld();
        BodyId a = one.AddCircle(10f, Vector2.Zero);
        BodyId b = two.AddCircle(10f, Vector2.Zero);
        BodyId again = a;
        Assert.Equal(a.Index, b.Index);
        Assert.True(a == again);
        Assert.True(a.Equals((object)again));
        Assert.Equal(a.GetHashCode(), again.GetHashCode());
        Assert.True(a != b);
        Assert.False(a.Equals((object)b));
        Assert.False(a.Equals("body 0"));
    }

    [Fact]
    public void TheDefaultIdNamesNoBody()
    {
        BodyId none = default;
        Assert.True(none.IsNull);
        Assert.Equal(-1, none.Index);
        Assert.False(none.IsStatic);
        Assert.Equal("no body", none.ToString());

        var world = new MotionWorld();
        BodyId first = world.AddCircle(10f, Vector2.Zero);
        Assert.NotEqual(first, none);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.PositionOf(none)).ParamName);
    }

    [Fact]
    public void AnIdOfAnotherMotionWorldIsRefusedByEveryMethodThatTakesABody()
    {
        // The same index in another motion world names a body there, not here: every method refuses it
        // instead of answering for this motion world's body 0.
        var world = new MotionWorld();
        BodyId mine = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        var other = new MotionWorld();
        BodyId theirs = other.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        var contacts = new FishContact[FishCollision.MaxContactsWithFish];
        Action[] calls =
        [
            () => world.KindOf(theirs),
            () => world.PositionOf(theirs),
            () => world.HeadingOf(theirs),
            () => world.VelocityOf(theirs),
            () => world.AngularVelocityOf(theirs),
            () => world.DriftOf(theirs),
            () => world.AngularDriftOf(theirs),
            () => world.FishModelOf(theirs),
            () => world.FishPoseOf(theirs),
            () => world.SetPose(theirs, Vector2.Zero, 0f),
            () => world.SetJoints(theirs, 0f, 0f, 0f),
            () => world.SetVelocity(theirs, Vector2.One),
            () => world.SetDrift(theirs, Vector2.One),
            () => world.SetCollides(theirs, false),
            () => world.Involve(theirs),
            () => world.WasRejected(theirs),
            () => world.TagOf(theirs),
            () => world.SetTag(theirs, 1),
            () => world.CollidesOf(theirs),
            () => world.Detect(theirs, mine),
            () => world.Detect(mine, theirs),
            () => world.DetectLeaves(theirs, mine, contacts),
            () => world.DetectLeaves(mine, theirs, contacts),
            () => world.RejectMove(theirs),
        ];
        foreach (Action call in calls)
        {
            var e = Assert.Throws<ArgumentException>(call);
            Assert.Contains("not a body of this motion world", e.Message, StringComparison.Ordinal);
        }

        Assert.Equal(0, world.TagOf(mine));
        Assert.True(world.CollidesOf(mine));
    }

    [Fact]
    public void ContactsAndRejectedMovesCarryTheIdsTheAddMethodsReturned()
    {
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(1000f, 800f, goalBlocks: false));
        BodyId block = world.AddStatic(new Aabb(new Vector2(-50f, -50f), new Vector2(50f, 50f)));
        var balls = new List<BodyId>();
        for (int i = 0; i < 6; i++)
        {
            BodyId ball = world.AddCircle(40f, new Vector2(-350f + (i * 140f), 250f - (i % 2 * 500f)));
            world.SetVelocity(ball, new Vector2(i % 2 == 0 ? 4000f : -3000f, i % 3 == 0 ? -2500f : 2500f));
            balls.Add(ball);
        }

        var known = new HashSet<BodyId>(balls) { walls, block };
        var handler = new RecordingHandler(restitution: 1f);
        for (int step = 0; step < 10; step++)
        {
            world.Step(0.1f, handler);
        }

        Assert.True(handler.Contacts.Count > 5, $"only {handler.Contacts.Count} contacts: the scene does not test the ids");
        foreach (Contact c in handler.Contacts)
        {
            Assert.Contains(c.BodyA, balls);
            Assert.Contains(c.BodyB, known);
            Assert.Equal(c.BodyB == walls || c.BodyB == block, c.BodyB.IsStatic);
        }

        foreach (BodyId rejected in handler.Rejected)
        {
            Assert.Contains(rejected, balls);
        }
    }
}
