namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// <see cref="MotionWorld.DetectLeaves"/>: every leaf contact of a fish with another body, as
/// <see cref="FishCollision.DetectAll(FishModel, FishModel, Span{FishContact})"/> gives them for
/// models built fresh at the two poses, without touching the world's own models or allocating.
/// </summary>
public sealed class MotionWorldLeafContactsTests
{
    private static readonly FishSize Small = new(120f, 35f, 22f, 66f, 50f, 41f);

    [Fact]
    public void TheContactsAreThoseOfFreshModelsAtThePosesNow()
    {
        var world = new MotionWorld();
        BodyId big = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        BodyId small = world.AddFish(Small, new FishPose(new Vector2(100f, 0f), 0f, 0f, 0f, 0f));
        BodyId other = world.AddFish(FishSize.Default, new FishPose(new Vector2(-100f, 0f), 0f, 0f, 0f, 0f));
        BodyId ball = world.AddCircle(58f, new Vector2(0f, 100f));
        Shape[] shapes =
        [
            new Circle(new Vector2(60f, -40f), 45f),
            new Aabb(new Vector2(-80f, -60f), new Vector2(40f, 10f)),
            KDop8.FromPoints([new Vector2(-50f, -50f), new Vector2(70f, -30f), new Vector2(10f, 60f)]),
            new ConvexPolygon([new Vector2(-60f, -20f), new Vector2(50f, -70f), new Vector2(80f, 40f), new Vector2(-30f, 50f)]),
            new Segment(new Vector2(-120f, 30f), new Vector2(90f, -50f)),
        ];
        var statics = new List<BodyId>();
        foreach (Shape shape in shapes)
        {
            statics.Add(world.AddStatic(shape));
        }

        var random = new Random(40);
        var got = new FishContact[FishCollision.MaxContactsWithFish];
        var want = new FishContact[FishCollision.MaxContactsWithFish];
        int compared = 0;
        for (int trial = 0; trial < 300; trial++)
        {
            foreach (BodyId f in (BodyId[])[big, small, other])
            {
                world.SetPose(f, new Vector2(Next(random, 150f), Next(random, 150f)), Next(random, 3f));
                world.SetJoints(f, Next(random, 0.5f), Next(random, 0.5f), Next(random, 0.5f));
            }

            world.SetPose(ball, new Vector2(Next(random, 150f), Next(random, 150f)), 0f);
            BodyId fish = trial % 2 == 0 ? big : small;
            FishModel a = new(fish == small ? Small : FishSize.Default, world.FishPoseOf(fish));
            foreach (BodyId partner in (BodyId[])[fish == big ? small : big, other, ball, .. statics])
            {
                int n = world.DetectLeaves(fish, partner, got);
                int expected = world.KindOf(partner) switch
                {
                    BodyKind.Fish => FishCollision.DetectAll(a, new FishModel(partner == small ? Small : FishSize.Default, world.FishPoseOf(partner)), want),
                    BodyKind.Circle => FishCollision.DetectAll(a, new Circle(world.PositionOf(partner), 58f), want),
                    _ => Static(a, shapes[statics.IndexOf(partner)], want),
                };
                Assert.Equal(expected, n);
                for (int i = 0; i < n; i++)
                {
                    Assert.Equal(want[i], got[i]);
                }

                compared += n;
            }
        }

        Assert.True(compared > 1000, $"only {compared} leaf contacts compared: the scene does not test the query");
    }

    [Fact]
    public void QueryingDuringAStepChangesNothingOfTheStep()
    {
        // Two runs of one scene of fish and balls: one handler asks for the leaf contacts of every
        // fish contact first, the other does not. The steps end bit for bit alike.
        (Vector2[] plain, int plainContacts) = Run(query: false);
        (Vector2[] queried, int queriedContacts) = Run(query: true);
        Assert.True(plainContacts > 0, "no contact: the scene does not test the query");
        Assert.Equal(plainContacts, queriedContacts);
        Assert.Equal(plain, queried);
    }

    [Fact]
    public void AfterWarmUpTheQueryAllocatesNothing()
    {
        var world = new MotionWorld();
        BodyId a = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0.2f, 0f, -0.2f));
        BodyId b = world.AddFish(Small, new FishPose(new Vector2(150f, 40f), 1f, 0f, 0.1f, 0f));
        BodyId ball = world.AddCircle(58f, new Vector2(0f, 60f));
        var contacts = new FishContact[FishCollision.MaxContactsWithFish];
        world.DetectLeaves(a, b, contacts);
        world.DetectLeaves(b, ball, contacts);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            world.DetectLeaves(a, b, contacts);
            world.DetectLeaves(b, a, contacts);
            world.DetectLeaves(a, ball, contacts);
        }

        Assert.Equal(0L, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    [Fact]
    public void WhatIsNotAFishOrHasNoShapeIsRefusedByName()
    {
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        BodyId ball = world.AddCircle(58f, new Vector2(0f, 60f));
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        var contacts = new FishContact[FishCollision.MaxContactsWithFish];
        Assert.Equal("fish", Assert.Throws<ArgumentException>(() => world.DetectLeaves(ball, fish, contacts)).ParamName);
        Assert.Equal("fish", Assert.Throws<ArgumentException>(() => world.DetectLeaves(default, fish, contacts)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.DetectLeaves(fish, walls, contacts)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.DetectLeaves(fish, fish, contacts)).ParamName);
        Assert.Equal("body", Assert.Throws<ArgumentException>(() => world.DetectLeaves(fish, new MotionWorld().AddCircle(58f, Vector2.Zero), contacts)).ParamName);
    }

    private static (Vector2[] Positions, int Contacts) Run(bool query)
    {
        var world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        var random = new Random(7);
        var ids = new List<BodyId>();
        for (int i = 0; i < 6; i++)
        {
            BodyId f = world.AddFish(i % 2 == 0 ? FishSize.Default : Small, new FishPose(new Vector2(-900f + (i * 350f), (i % 3 * 300f) - 300f), i, 0.2f, -0.1f, 0.1f));
            world.SetVelocity(f, new Vector2(Next(random, 2500f), Next(random, 2500f)), Next(random, 4f));
            ids.Add(f);
        }

        for (int i = 0; i < 6; i++)
        {
            BodyId b = world.AddCircle(58f, new Vector2(-800f + (i * 320f), 400f - (i % 2 * 700f)));
            world.SetVelocity(b, new Vector2(Next(random, 3000f), Next(random, 3000f)));
            ids.Add(b);
        }

        var handler = new QueryingHandler(query);
        for (int step = 0; step < 20; step++)
        {
            world.Step(0.1f, handler);
        }

        var positions = new Vector2[ids.Count];
        for (int i = 0; i < ids.Count; i++)
        {
            positions[i] = world.PositionOf(ids[i]);
        }

        return (positions, handler.Inner.Contacts.Count);
    }

    private static int Static(FishModel a, in Shape shape, Span<FishContact> into) => shape.Kind switch
    {
        ShapeKind.Circle => FishCollision.DetectAll(a, shape.AsCircle(), into),
        ShapeKind.Aabb => FishCollision.DetectAll(a, shape.AsAabb(), into),
        ShapeKind.KDop8 => FishCollision.DetectAll(a, shape.AsKDop8(), into),
        ShapeKind.Polygon => FishCollision.DetectAll(a, shape.AsPolygon(), into),
        _ => FishCollision.DetectAll(a, shape.AsSegment(), into),
    };

    private static float Next(Random random, float half) => (random.NextSingle() * 2f * half) - half;

    // Asks for the leaf contacts of every contact of a fish (when told to), then responds as the recording handler does.
    private sealed class QueryingHandler(bool query) : IContactHandler
    {
        private readonly FishContact[] _contacts = new FishContact[FishCollision.MaxContactsWithFish];

        public RecordingHandler Inner { get; } = new(restitution: 0.5f);

        public void OnContact(MotionWorld world, in Contact contact)
        {
            if (query && world.KindOf(contact.BodyA) == BodyKind.Fish && world.KindOf(contact.BodyB) != BodyKind.Walls)
            {
                world.DetectLeaves(contact.BodyA, contact.BodyB, _contacts);
            }

            Inner.OnContact(world, contact);
        }

        public void OnMoveRejected(MotionWorld world, BodyId body) => Inner.OnMoveRejected(world, body);
    }
}
