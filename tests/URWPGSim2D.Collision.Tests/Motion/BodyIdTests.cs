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

    [Fact]
    public void ClearMakesEveryIdStaleAndTheNewBodiesNumberFromZero()
    {
        var world = new MotionWorld { Wedging = new WedgePolicy { CorrectionsBeforeRejecting = 3 } };
        BodyId old = world.AddCircle(50f, Vector2.Zero);
        BodyId oldFish = world.AddFish(FishSize.Default, new FishPose(new Vector2(-400f, 0f), 0f, 0f, 0f, 0f));
        world.AddCircle(50f, new Vector2(90f, 0f));
        Assert.Equal(10f, world.Detect(old, world.IdAt(2)).Depth, 3);
        world.Step(0.1f, new RecordingHandler());

        world.Clear();
        Assert.Equal(0, world.BodyCount);
        Assert.Equal(3, world.Wedging.CorrectionsBeforeRejecting);

        // The new body 0 is not the old one: the old id is refused as stale, by name.
        BodyId ball = world.AddCircle(20f, Vector2.Zero);
        Assert.Equal(old.Index, ball.Index);
        Assert.NotEqual(old, ball);
        (Action Call, string Id, string Parameter)[] calls =
        [
            (() => world.PositionOf(old), "body 0", "body"),
            (() => world.SetTag(old, 1), "body 0", "body"),
            (() => world.WasRejected(old), "body 0", "body"),
            (() => world.FishPoseOf(oldFish), "body 1", "fish"),
        ];
        foreach (var (call, id, parameter) in calls)
        {
            var refused = Assert.Throws<ArgumentException>(call);
            Assert.StartsWith(id + " is stale: its body was removed when the motion world was cleared", refused.Message, StringComparison.Ordinal);
            Assert.Equal(parameter, refused.ParamName);
            Assert.DoesNotContain('\n', refused.Message);
        }

        // The new bodies are what was added since: two balls of radii 20 and 30 whose centres are
        // 40 mm apart overlap by 10 mm, whatever the old bodies at those places were.
        BodyId other = world.AddCircle(30f, new Vector2(40f, 0f));
        Assert.Equal(10f, world.Detect(ball, other).Depth, 3);
        world.SetTag(ball, 41);
        Assert.Equal(41, world.TagOf(ball));
        Assert.Equal(0, world.TagOf(other));

        // And they move: the ball thrown at the other meets it within the step, the contact names the new ids.
        world.SetPose(ball, new Vector2(-200f, 0f), 0f);
        world.SetVelocity(ball, new Vector2(3000f, 0f));
        var handler = new RecordingHandler();
        world.Step(0.1f, handler);
        Assert.NotEmpty(handler.Contacts);
        Assert.All(handler.Contacts, c => Assert.True((c.BodyA == ball && c.BodyB == other) || (c.BodyA == other && c.BodyB == ball), $"{c.BodyA} and {c.BodyB}"));
        Assert.True(world.MeasureOverlap() <= 0.5f);
    }

    [Fact]
    public void ClearIsRefusedWhileAStepRuns()
    {
        var world = new MotionWorld();
        world.AddCircle(50f, Vector2.Zero);
        world.AddCircle(50f, new Vector2(90f, 0f));
        var handler = new ClearingHandler();
        world.Settle(handler);
        Assert.NotNull(handler.Refused);
        Assert.Equal(2, world.BodyCount);
    }

    private sealed class ClearingHandler : IContactHandler
    {
        public InvalidOperationException? Refused { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            try
            {
                world.Clear();
            }
            catch (InvalidOperationException e)
            {
                Refused ??= e;
            }

            world.SetPose(contact.BodyA, world.PositionOf(contact.BodyA) + (XZPlane.ToPlane(contact.Result.MinimumTranslationVector) * 1.01f), 0f);
        }

        public void OnMoveRejected(MotionWorld world, BodyId body)
        {
        }
    }
}
