namespace URWPGSim2D.Collision.Tests.Motion;

public sealed class BodyIdTests
{
    [Fact]
    public void IdsNumberTheBodiesInTheOrderAddedAndTellTheStaticOnes()
    {
        var stepper = new Stepper();
        BodyId[] ids =
        [
            stepper.AddStatic(new Circle(new Vector2(500f, 0f), 40f)),
            stepper.AddFish(FishSize.Default, new FishPose(new Vector2(-400f, 0f), 0f, 0f, 0f, 0f)),
            stepper.AddWalls(new Field(3000f, 2000f, goalBlocks: false)),
            stepper.AddCircle(58f, new Vector2(0f, 300f)),
            stepper.AddPolygon(new ConvexPolygon([new Vector2(-20f, -10f), new Vector2(20f, -10f), new Vector2(0f, 15f)]), new Vector2(0f, -300f), 0.5f),
        ];
        bool[] isStatic = [true, false, true, false, false];
        BodyKind[] kinds = [BodyKind.Static, BodyKind.Fish, BodyKind.Walls, BodyKind.Circle, BodyKind.Polygon];
        for (int i = 0; i < ids.Length; i++)
        {
            Assert.Equal(i, ids[i].Index);
            Assert.Equal(isStatic[i], ids[i].IsStatic);
            Assert.False(ids[i].IsNull);
            Assert.Equal(kinds[i], stepper.KindOf(ids[i]));
            Assert.Equal((isStatic[i] ? "static body " : "body ") + i, ids[i].ToString());
        }

        Assert.Equal(ids.Length, new HashSet<BodyId>(ids).Count);
    }

    [Fact]
    public void AnIdEqualsItselfOnlyNotTheSameIndexOfAnotherStepper()
    {
        var one = new Stepper();
        var two = new Stepper();
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

        var stepper = new Stepper();
        BodyId first = stepper.AddCircle(10f, Vector2.Zero);
        Assert.NotEqual(first, none);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => stepper.PositionOf(none)).ParamName);
    }

    [Fact]
    public void AnIdOfAnotherStepperIsRefusedByEveryMethodThatTakesABody()
    {
        // The same index in another stepper names a body there, not here: every method refuses it
        // instead of answering for this stepper's body 0.
        var stepper = new Stepper();
        BodyId mine = stepper.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        var other = new Stepper();
        BodyId theirs = other.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        var contacts = new FishContact[FishCollision.MaxContactsWithFish];
        Action[] calls =
        [
            () => stepper.KindOf(theirs),
            () => stepper.PositionOf(theirs),
            () => stepper.HeadingOf(theirs),
            () => stepper.VelocityOf(theirs),
            () => stepper.AngularVelocityOf(theirs),
            () => stepper.DriftOf(theirs),
            () => stepper.AngularDriftOf(theirs),
            () => stepper.FishModelOf(theirs),
            () => stepper.FishPoseOf(theirs),
            () => stepper.SetPose(theirs, Vector2.Zero, 0f),
            () => stepper.SetJoints(theirs, 0f, 0f, 0f),
            () => stepper.SetVelocity(theirs, Vector2.One),
            () => stepper.SetDrift(theirs, Vector2.One),
            () => stepper.SetCollides(theirs, false),
            () => stepper.Involve(theirs),
            () => stepper.WasRejected(theirs),
            () => stepper.TagOf(theirs),
            () => stepper.SetTag(theirs, 1),
            () => stepper.CollidesOf(theirs),
            () => stepper.Detect(theirs, mine),
            () => stepper.Detect(mine, theirs),
            () => stepper.DetectLeaves(theirs, mine, contacts),
            () => stepper.DetectLeaves(mine, theirs, contacts),
            () => stepper.RejectMove(theirs),
        ];
        foreach (Action call in calls)
        {
            var e = Assert.Throws<ArgumentException>(call);
            Assert.Contains("not a body of this stepper", e.Message, StringComparison.Ordinal);
        }

        Assert.Equal(0, stepper.TagOf(mine));
        Assert.True(stepper.CollidesOf(mine));
    }

    [Fact]
    public void ContactsAndRejectedMovesCarryTheIdsTheAddMethodsReturned()
    {
        var stepper = new Stepper();
        BodyId walls = stepper.AddWalls(new Field(1000f, 800f, goalBlocks: false));
        BodyId block = stepper.AddStatic(new Aabb(new Vector2(-50f, -50f), new Vector2(50f, 50f)));
        var balls = new List<BodyId>();
        for (int i = 0; i < 6; i++)
        {
            BodyId ball = stepper.AddCircle(40f, new Vector2(-350f + (i * 140f), 250f - (i % 2 * 500f)));
            stepper.SetVelocity(ball, new Vector2(i % 2 == 0 ? 4000f : -3000f, i % 3 == 0 ? -2500f : 2500f));
            balls.Add(ball);
        }

        var known = new HashSet<BodyId>(balls) { walls, block };
        var handler = new RecordingHandler(restitution: 1f);
        for (int step = 0; step < 10; step++)
        {
            stepper.Step(0.1f, handler);
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
