namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The motion world's queries (ray casts, overlaps, nearest body) against brute force — every body
/// tested with <see cref="ShapeQuery"/> and <see cref="CollisionDetector"/> on its shape rebuilt from
/// the public state, the walls by hand — on random scenes of fish, balls, moving polygons, static
/// shapes of every kind, goal blocks and the walls; and the queries allocate nothing.
/// </summary>
public sealed class MotionWorldQueryTests
{
    private const float Tolerance = 1e-3f;

    public static TheoryData<int> Seeds => [1, 2, 3];

    [Theory]
    [MemberData(nameof(Seeds))]
    public void RayCastsMatchBruteForce(int seed)
    {
        var scene = new Scene(seed);
        int entered = CheckRays(scene, new Random(seed * 7), 300, 1.2f);
        Assert.True(entered > 300, $"only {entered} entries in 300 rays: the scene does not exercise the ray casts");
    }

    [Theory]
    [MemberData(nameof(Seeds))]
    public void OverlapsMatchBruteForce(int seed)
    {
        var scene = new Scene(seed);
        var kinds = CheckOverlaps(scene, new Random(seed * 11), 300);
        Assert.Equal(Enum.GetValues<BodyKind>().Length, kinds.Count);
    }

    [Theory]
    [MemberData(nameof(Seeds))]
    public void NearestMatchesBruteForce(int seed)
    {
        var scene = new Scene(seed);
        var kinds = CheckNearest(scene, new Random(seed * 13), 300);
        Assert.True(kinds.Count >= 4, $"the nearest bodies were only {string.Join(", ", kinds)}");
    }

    [Theory]
    [MemberData(nameof(Seeds))]
    public void QueriesFollowBodiesPlacedAndReplacedBetweenThem(int seed)
    {
        var scene = new Scene(seed);
        var random = new Random(seed * 17);
        int entered = 0;
        for (int round = 0; round < 12; round++)
        {
            // A few bodies placed, or (every third round) many more placements than bodies, some far away.
            int moves = round % 3 == 2 ? 3 * scene.World.BodyCount : 1 + random.Next(4);
            for (int k = 0; k < moves; k++)
            {
                scene.PlaceRandomMover(random, far: random.Next(4) == 0);
            }

            if (round % 4 == 1)
            {
                scene.ReplaceRandomBody(random);
            }

            entered += CheckRays(scene, random, 40, 1.2f);
            CheckOverlaps(scene, random, 40);
            CheckNearest(scene, random, 40);
        }

        Assert.True(entered > 100, $"only {entered} entries: the rays miss the scene");
    }

    [Theory]
    [MemberData(nameof(Seeds))]
    public void QueriesFollowTheBodiesThroughAStepAndFromItsHandler(int seed)
    {
        var scene = new Scene(seed);
        var random = new Random(seed * 19);
        scene.GiveMoversVelocities(random, 2000f);
        var handler = new QueryingHandler(scene, random);
        for (int step = 0; step < 4; step++)
        {
            scene.World.Step(0.1f, handler);
            CheckRays(scene, random, 40, 1.2f);
            CheckOverlaps(scene, random, 40);
            CheckNearest(scene, random, 40);
        }

        Assert.True(handler.Calls > 10, $"only {handler.Calls} contacts queried from");
    }

    [Fact]
    public void QueriesFollowAWorldClearedAndFilledAgain()
    {
        var scene = new Scene(4);
        var random = new Random(23);
        CheckNearest(scene, random, 50);
        var again = new Scene(5, 25, scene.World);
        CheckRays(again, random, 100, 1.2f);
        CheckOverlaps(again, random, 100);
        CheckNearest(again, random, 100);
        scene.World.Clear();
        Assert.True(scene.World.Nearest(Vector2.Zero).Id.IsNull);
        Assert.Equal(0, scene.World.RayCastAll(new Vector2(-2000f, 0f), new Vector2(2000f, 0f), Span<BodyRayHit>.Empty));
    }

    [Fact]
    public void ManyBodiesMatchBruteForce()
    {
        var scene = new Scene(6, 1000);
        var random = new Random(29);
        Assert.InRange(scene.World.QueryTree.Height, 10, 2 * 10);
        CheckRays(scene, random, 60, 1.2f);
        CheckOverlaps(scene, random, 60);
        CheckNearest(scene, random, 60);
        for (int k = 0; k < 300; k++)
        {
            scene.PlaceRandomMover(random, far: false);
        }

        Assert.InRange(scene.World.QueryTree.Height, 10, 2 * 10);
        CheckRays(scene, random, 60, 1.2f);
        CheckOverlaps(scene, random, 60);
        CheckNearest(scene, random, 60);
    }

    [Fact]
    public void RaysThatMissEverythingFindNothing()
    {
        var scene = new Scene(7);
        var random = new Random(31);
        var hits = new BodyRayHit[4];
        for (int q = 0; q < 200; q++)
        {
            // Outside the pool (the walls are entered only from inside), or between two far points on one side of it.
            Vector2 from = new(3000f + (random.NextSingle() * 5000f), (random.NextSingle() - 0.5f) * 8000f);
            Vector2 to = q % 2 == 0 ? from + new Vector2(random.NextSingle() * 2000f, (random.NextSingle() - 0.5f) * 2000f) : from;
            Assert.True(scene.World.RayCast(from, to).Id.IsNull, $"ray {q} from {from} to {to} hit something");
            Assert.Equal(0, scene.World.RayCastAll(from, to, hits));
        }

        // Inside the pool, the walls alone: a ray along an empty strip just inside the long side.
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field());
        world.AddStatic(new Circle(Vector2.Zero, 100f));
        Assert.True(world.RayCast(new Vector2(-500f, 900f), new Vector2(500f, 900f)).Id.IsNull);
        Assert.Equal(walls, world.RayCast(new Vector2(-500f, 900f), new Vector2(-500f, 1100f)).Id);
        CheckRays(scene, random, 100, 3f);
    }

    [Fact]
    public void TiesGoToTheLowerNumber()
    {
        // Every shape three times (numbers k, k + 40, k + 80): equal answers, bit for bit, wherever the tree keeps them.
        var world = new MotionWorld();
        var random = new Random(37);
        var shapes = new Shape[40];
        for (int i = 0; i < shapes.Length; i++)
        {
            shapes[i] = RandomShape(random, new Vector2((random.NextSingle() - 0.5f) * 3000f, (random.NextSingle() - 0.5f) * 2000f));
        }

        for (int copy = 0; copy < 3; copy++)
        {
            foreach (Shape shape in shapes)
            {
                world.AddStatic(shape);
            }
        }

        var hits = new BodyRayHit[120];
        var found = new BodyId[120];
        int ties = 0;
        for (int q = 0; q < 300; q++)
        {
            Vector2 a = new((random.NextSingle() - 0.5f) * 3000f, (random.NextSingle() - 0.5f) * 2000f);
            Vector2 b = new((random.NextSingle() - 0.5f) * 3000f, (random.NextSingle() - 0.5f) * 2000f);
            BodyDistance nearest = world.Nearest(a);
            Assert.True(nearest.Body < 40, $"point {q}: {nearest} is a later copy");
            BodyRayHit first = world.RayCast(a, b);
            int count = world.RayCastAll(a, b, hits);
            Assert.Equal(0, count % 3);
            if (count == 0)
            {
                Assert.True(first.Id.IsNull);
                continue;
            }

            Assert.True(first.Body < 40, $"ray {q}: {first} is a later copy");
            Assert.Equal(first.Id, hits[0].Id);
            InOrder(hits.AsSpan(0, count), q);
            for (int k = 0; k < count; k++)
            {
                int copies = 0;
                for (int j = 0; j < count; j++)
                {
                    copies += hits[j].Body % 40 == hits[k].Body % 40 ? 1 : 0;
                }

                Assert.Equal(3, copies);
            }

            ties += count / 3;
            int overlapping = world.Overlap(new Circle(a, 150f), found);
            Assert.Equal(0, overlapping % 3);
            for (int k = 1; k < overlapping; k++)
            {
                Assert.True(found[k - 1].Index < found[k].Index);
            }
        }

        Assert.True(ties > 100, $"only {ties} tied entries");
    }

    // Rays between random points against brute force: the first body, every body in order (equal
    // fractions by number), a short span given the first ones. Returns the entries.
    private static int CheckRays(Scene scene, Random random, int rays, float spread)
    {
        var hits = new BodyRayHit[scene.World.BodyCount];
        var few = new BodyRayHit[3];
        int entered = 0;
        for (int q = 0; q < rays; q++)
        {
            Vector2 from = scene.RandomPoint(random, spread), to = scene.RandomPoint(random, spread);
            var expected = new List<(int Index, RayCastResult Hit)>();
            for (int i = 0; i < scene.World.BodyCount; i++)
            {
                RayCastResult hit = scene.RayCast(i, from, to);
                if (hit.Hit)
                {
                    expected.Add((i, hit));
                }
            }

            BodyRayHit first = scene.World.RayCast(from, to);
            int count = scene.World.RayCastAll(from, to, hits);
            var missing = expected.Select(e => e.Index).Except(hits.Take(count).Select(h => h.Body));
            var extra = hits.Take(count).Select(h => h.Body).Except(expected.Select(e => e.Index));
            Assert.True(expected.Count == count, $"ray {q} from {from} to {to}: {count} bodies entered, brute force {expected.Count}; missing {string.Join(", ", missing.Select(i => $"{i} ({scene.World.KindOf(scene.World.IdAt(i))})"))}; extra {string.Join(", ", extra)}");
            if (expected.Count == 0)
            {
                Assert.True(first.Id.IsNull, $"ray {q}: no body is entered, got {first}");
                continue;
            }

            entered += count;
            float least = expected.Min(e => e.Hit.Fraction);
            Assert.False(first.Id.IsNull, $"ray {q}: {expected.Count} bodies are entered, got none");
            var mine = expected.Single(e => e.Index == first.Body);
            Assert.True(mine.Hit.Fraction <= least + Tolerance, $"ray {q}: {first} is not the first body entered (fraction {least})");
            Same(mine.Hit, first.Result, q);
            Assert.Equal(expected.Select(e => e.Index).OrderBy(i => i), hits.Take(count).Select(h => h.Body).OrderBy(i => i));
            for (int k = 0; k < count; k++)
            {
                Same(expected.Single(e => e.Index == hits[k].Body).Hit, hits[k].Result, q);
                Assert.Equal(scene.World.IdAt(hits[k].Body), hits[k].Id);
            }

            InOrder(hits.AsSpan(0, count), q);
            Assert.Equal(hits[0].Id, first.Id);
            Assert.Equal(count, scene.World.RayCastAll(from, to, few));
            Assert.Equal(hits.Take(Math.Min(count, few.Length)), few.Take(Math.Min(count, few.Length)));
        }

        return entered;
    }

    // Random shapes against brute force: the ids by ascending number, a short span given the first ones.
    private static HashSet<BodyKind> CheckOverlaps(Scene scene, Random random, int shapes)
    {
        var found = new BodyId[scene.World.BodyCount];
        var kinds = new HashSet<BodyKind>();
        var two = new BodyId[2];
        for (int q = 0; q < shapes; q++)
        {
            Shape shape = RandomShape(random, scene.RandomPoint(random, 1.1f));
            var expected = new List<int>();
            for (int i = 0; i < scene.World.BodyCount; i++)
            {
                if (scene.Overlaps(i, shape))
                {
                    expected.Add(i);
                    kinds.Add(scene.World.KindOf(scene.World.IdAt(i)));
                }
            }

            int count = scene.World.Overlap(shape, found);
            Assert.Equal(expected, found.Take(count).Select(b => b.Index));
            Assert.All(found.Take(count), b => Assert.Equal(scene.World.IdAt(b.Index), b));

            // A short span is filled with the first ones and the count stays whole.
            Assert.Equal(count, scene.World.Overlap(shape, two));
            for (int k = 0; k < Math.Min(2, count); k++)
            {
                Assert.Equal(found[k], two[k]);
            }
        }

        return kinds;
    }

    // Random points against brute force: the nearest body and its distance.
    private static HashSet<BodyKind> CheckNearest(Scene scene, Random random, int points)
    {
        var kinds = new HashSet<BodyKind>();
        for (int q = 0; q < points; q++)
        {
            Vector2 point = scene.RandomPoint(random, 1.1f);
            var distances = Enumerable.Range(0, scene.World.BodyCount).Select(i => scene.Distance(i, point)).ToArray();
            float least = distances.Min(d => d.Distance);
            BodyDistance nearest = scene.World.Nearest(point);
            Assert.False(nearest.Id.IsNull);
            DistanceResult mine = distances[nearest.Body];
            Assert.True(mine.Distance <= least + Tolerance, $"point {q}: {nearest} is not the nearest body ({least} mm)");
            Assert.Equal(mine.Distance, nearest.Result.Distance, Tolerance);
            Assert.True(Vector2.Distance(mine.PointA, nearest.Result.PointA) <= Tolerance, $"point {q}: {nearest} against {mine}");
            Assert.Equal(point, nearest.Result.PointB);
            Assert.Equal(mine.PartA, nearest.Result.PartA);
            Assert.Equal(scene.World.IdAt(nearest.Body), nearest.Id);
            kinds.Add(scene.World.KindOf(nearest.Id));
        }

        return kinds;
    }

    // Nearest first, equal fractions by ascending number.
    private static void InOrder(ReadOnlySpan<BodyRayHit> hits, int ray)
    {
        for (int k = 1; k < hits.Length; k++)
        {
            float a = hits[k - 1].Result.Fraction, b = hits[k].Result.Fraction;
            Assert.True(a < b || (a == b && hits[k - 1].Body < hits[k].Body), $"ray {ray}: hits {k - 1} and {k} out of order ({hits[k - 1]}, {hits[k]})");
        }
    }

    [Fact]
    public void AnEmptyWorldAnswersNothing()
    {
        var world = new MotionWorld();
        Assert.True(world.Nearest(Vector2.Zero).Id.IsNull);
        Assert.True(world.RayCast(Vector2.Zero, Vector2.One).Id.IsNull);
        Assert.Equal(0, world.Overlap(new Aabb(-Vector2.One, Vector2.One), Span<BodyId>.Empty));
    }

    [Fact]
    public void TheWallsAreTheOutsideOfThePool()
    {
        var world = new MotionWorld();
        BodyId walls = world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        BodyRayHit hit = world.RayCast(new Vector2(0f, 0f), new Vector2(3000f, 0f));
        Assert.Equal(walls, hit.Id);
        Assert.Equal(0.5f, hit.Result.Fraction);
        Assert.Equal(new Vector2(-1f, 0f), hit.Result.Normal);
        Assert.True(world.RayCast(new Vector2(1600f, 0f), new Vector2(0f, 0f)).Id.IsNull);
        Assert.True(world.RayCast(new Vector2(0f, 0f), new Vector2(100f, 0f)).Id.IsNull);
        Assert.Equal(100f, world.Nearest(new Vector2(1400f, 0f)).Result.Distance);
        Assert.Equal(0f, world.Nearest(new Vector2(1600f, 0f)).Result.Distance);
        Span<BodyId> found = stackalloc BodyId[1];
        Assert.Equal(0, world.Overlap(new Circle(new Vector2(1400f, 0f), 100f), found));
        Assert.Equal(1, world.Overlap(new Circle(new Vector2(1400f, 0f), 100.5f), found));
    }

    [Fact]
    public void AStaticReplacedIsSeenByQueriesAndSteps()
    {
        var world = new MotionWorld();
        BodyId obstacle = world.AddStatic(new Circle(Vector2.Zero, 50f));
        BodyId ball = world.AddCircle(20f, new Vector2(-300f, 0f));
        world.SetVelocity(ball, new Vector2(1000f, 0f));
        Assert.Equal(obstacle, world.ReplaceByStatic(obstacle, new Circle(new Vector2(0f, 500f), 50f)));
        Assert.Equal(obstacle, world.RayCast(new Vector2(0f, 0f), new Vector2(0f, 1000f)).Id);
        var handler = new RecordingHandler(0.3f);
        world.Step(0.5f, handler);
        Assert.Empty(handler.Contacts);
        Assert.Equal(200f, world.PositionOf(ball).X, 1e-3f);

        world.ReplaceByStatic(obstacle, new Aabb(new Vector2(300f, -100f), new Vector2(400f, 100f)));
        world.Step(0.5f, handler);
        Assert.NotEmpty(handler.Contacts);
        Assert.All(handler.Contacts, c => Assert.Equal(obstacle, c.BodyB));
    }

    [Fact]
    public void AQueryWorldUpdatesItsShapesWithoutAllocating()
    {
        var world = new QueryWorld();
        int ball = world.Add(new Circle(Vector2.Zero, 10f));
        world.Update(ball, new Circle(Vector2.One, 10f));
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            world.Update(ball, new Circle(new Vector2(i, 0f), 10f));
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal(0L, allocated);
        Assert.Equal(ball, world.Nearest(new Vector2(99f, 100f)).Body);
        Assert.Equal(90f, world.Nearest(new Vector2(99f, 100f)).Result.Distance, 1e-3f);
    }

    [Fact]
    public void BadArgumentsAreRefusedByName()
    {
        var world = new MotionWorld();
        world.AddCircle(10f, Vector2.Zero);
        Assert.Equal("from", Assert.Throws<ArgumentException>(() => world.RayCast(new Vector2(float.NaN, 0f), Vector2.Zero)).ParamName);
        Assert.Equal("to", Assert.Throws<ArgumentException>(() => world.RayCastAll(Vector2.Zero, new Vector2(0f, float.PositiveInfinity), Span<BodyRayHit>.Empty)).ParamName);
        Assert.Equal("point", Assert.Throws<ArgumentException>(() => world.Nearest(new Vector2(float.NaN, 0f))).ParamName);
    }

    [Fact]
    public void QueriesAllocateNothing()
    {
        MotionWorld world = MotionWorldAllocationTests.World(100);
        var handler = new RecordingHandler(0.3f) { Record = false };
        var random = new Random(5);
        var hits = new BodyRayHit[16];
        var found = new BodyId[16];
        Shape polygon = new ConvexPolygon([new Vector2(0f, 0f), new Vector2(300f, 50f), new Vector2(100f, 250f)]);
        long allocated = 0, answers = 0;
        for (int round = 0; round < 6; round++)
        {
            world.Step(0.1f, handler);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int q = 0; q < 200; q++)
            {
                var from = new Vector2(random.NextSingle() * 3000f - 1500f, random.NextSingle() * 2000f - 1000f);
                var to = new Vector2(random.NextSingle() * 3000f - 1500f, random.NextSingle() * 2000f - 1000f);
                answers += world.RayCast(from, to).Id.IsNull ? 0 : 1;
                answers += world.RayCastAll(from, to, hits);
                answers += world.Overlap(new Aabb(Vector2.Min(from, to), Vector2.Max(from, to)), found);
                answers += world.Overlap(polygon, found);
                answers += world.Overlap(new Circle(from, 200f), found);
                answers += world.Nearest(to).Body;
            }

            // The first round warms up (the JIT, the fish models' first rebuild).
            if (round > 0)
            {
                allocated += GC.GetAllocatedBytesForCurrentThread() - before;
            }
        }

        Assert.True(answers > 1000, $"only {answers} answers: the queries find nothing");
        Assert.Equal(0L, allocated);
    }

    private static void Same(in RayCastResult expected, in RayCastResult actual, int ray)
    {
        Assert.True(actual.Hit, $"ray {ray}: no hit");
        Assert.Equal(expected.Fraction, actual.Fraction, Tolerance);
        Assert.True(Vector2.Distance(expected.Point, actual.Point) <= 0.01f, $"ray {ray}: {actual} against {expected}");
        Assert.Equal(expected.Part, actual.Part);
    }

    private static Shape RandomShape(Random random, Vector2 at)
    {
        float size = 20f + (random.NextSingle() * 400f);
        Vector2 Near() => at + new Vector2((random.NextSingle() - 0.5f) * size, (random.NextSingle() - 0.5f) * size);
        switch (random.Next(5))
        {
            case 0:
                return new Circle(at, size / 2f);
            case 1:
                return new Aabb(at - new Vector2(size / 2f, size / 3f), at + new Vector2(size / 2f, size / 3f));
            case 2:
                return new Segment(at, Near());
            case 3:
                return KDop8.FromPoints([at, Near(), Near(), Near()]);
            default:
                return new ConvexPolygon([at + new Vector2(-size / 2f, -size / 3f), at + new Vector2(size / 2f, -size / 4f), at + new Vector2(0f, size / 2f)]);
        }
    }

    // The recording handler's response, and a few queries against brute force at every contact,
    // where the bodies are at that moment.
    private sealed class QueryingHandler(Scene scene, Random random) : IContactHandler
    {
        private readonly RecordingHandler _response = new(0.3f) { Record = false };

        public int Calls { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            _response.OnContact(world, contact);
            if (Calls++ % 3 == 0)
            {
                CheckRays(scene, random, 2, 1.2f);
                CheckOverlaps(scene, random, 2);
                CheckNearest(scene, random, 2);
            }
        }

        public void OnMoveRejected(MotionWorld world, BodyId body) => _response.OnMoveRejected(world, body);
    }

    // A random scene and, for each body, its shape rebuilt from the public state.
    private sealed class Scene
    {
        private readonly Dictionary<int, Shape> _statics = [];
        private readonly Dictionary<int, float> _radii = [];
        private readonly Dictionary<int, ConvexPolygon> _polygons = [];

        public Scene(int seed, int bodies = 40, MotionWorld? world = null)
        {
            var random = new Random(seed);
            Field = new Field();
            World = world ?? new MotionWorld();
            World.Clear();
            World.AddWalls(Field);
            foreach (Aabb block in Field.GoalBlocks)
            {
                _statics[World.AddStatic(block).Index] = block;
            }

            for (int i = 0; i < bodies; i++)
            {
                Vector2 at = RandomPoint(random, 0.95f);
                float heading = (random.NextSingle() * 7f) - 3.5f;
                switch (i % 5)
                {
                    case 0:
                        World.AddFish(FishSize.Default, new FishPose(at, heading, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
                        break;
                    case 1:
                    {
                        float radius = 20f + (random.NextSingle() * 60f);
                        _radii[World.AddCircle(radius, at).Index] = radius;
                        break;
                    }

                    case 2:
                    {
                        var local = new ConvexPolygon([new Vector2(-40f, -25f), new Vector2(50f, -20f), new Vector2(60f, 30f), new Vector2(-30f, 35f)]);
                        _polygons[World.AddPolygon(local, at, heading).Index] = local;
                        break;
                    }

                    default:
                    {
                        Shape shape = RandomShape(random, at);
                        _statics[World.AddStatic(shape).Index] = shape;
                        break;
                    }
                }
            }
        }

        public Field Field { get; }

        public MotionWorld World { get; }

        // Places a random moving body somewhere in the pool (or far outside it), a fish with new joints too.
        public void PlaceRandomMover(Random random, bool far)
        {
            var movers = Enumerable.Range(0, World.BodyCount).Where(i => World.KindOf(World.IdAt(i)) <= BodyKind.Fish).ToArray();
            BodyId id = World.IdAt(movers[random.Next(movers.Length)]);
            Vector2 at = far ? RandomPoint(random, 1f) + new Vector2(5000f, 0f) : RandomPoint(random, 0.95f);
            World.SetPose(id, at, (random.NextSingle() * 7f) - 3.5f);
            if (World.KindOf(id) == BodyKind.Fish)
            {
                World.SetJoints(id, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f);
            }
        }

        // Replaces a random body (a fish or a static one) by a new static shape.
        public void ReplaceRandomBody(Random random)
        {
            var candidates = Enumerable.Range(0, World.BodyCount).Where(i => World.KindOf(World.IdAt(i)) is BodyKind.Fish or BodyKind.Static).ToArray();
            int index = candidates[random.Next(candidates.Length)];
            Shape shape = RandomShape(random, RandomPoint(random, 0.95f));
            World.ReplaceByStatic(World.IdAt(index), shape);
            _statics[index] = shape;
        }

        public void GiveMoversVelocities(Random random, float speed)
        {
            for (int i = 0; i < World.BodyCount; i++)
            {
                BodyId id = World.IdAt(i);
                if (World.KindOf(id) <= BodyKind.Fish)
                {
                    World.SetVelocity(id, new Vector2(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f) * speed, random.NextSingle() - 0.5f);
                }
            }
        }

        public Vector2 RandomPoint(Random random, float spread) =>
            new((random.NextSingle() - 0.5f) * Field.Length * spread, (random.NextSingle() - 0.5f) * Field.Width * spread);

        public RayCastResult RayCast(int index, Vector2 from, Vector2 to)
        {
            BodyId id = World.IdAt(index);
            return World.KindOf(id) switch
            {
                BodyKind.Fish => ShapeQuery.RayCast(World.FishModelOf(id), from, to),
                BodyKind.Walls => WallsRay(from, to),
                _ => ShapeQuery.RayCast(ShapeOf(index), from, to),
            };
        }

        public bool Overlaps(int index, in Shape shape)
        {
            BodyId id = World.IdAt(index);
            switch (World.KindOf(id))
            {
                case BodyKind.Fish:
                    return FishCollision.Detect(shape, World.FishModelOf(id)).Intersect;
                case BodyKind.Walls:
                {
                    // Any point of the shape strictly outside the pool: its extremes, sampled all round.
                    for (int k = 0; k < 720; k++)
                    {
                        float angle = k * MathF.PI / 360f;
                        var direction = new Vector2(MathF.Cos(angle), MathF.Sin(angle));
                        Vector2 far = Extreme(shape, direction);
                        if (MathF.Abs(far.X) > Field.Length / 2f + 1e-3f || MathF.Abs(far.Y) > Field.Width / 2f + 1e-3f)
                        {
                            return true;
                        }
                    }

                    return false;
                }

                default:
                    return CollisionDetector.Detect(shape, ShapeOf(index)).Intersect;
            }
        }

        public DistanceResult Distance(int index, Vector2 point)
        {
            BodyId id = World.IdAt(index);
            switch (World.KindOf(id))
            {
                case BodyKind.Fish:
                    return ShapeQuery.Distance(World.FishModelOf(id), point);
                case BodyKind.Walls:
                {
                    float hx = Field.Length / 2f, hz = Field.Width / 2f;
                    float d = MathF.Min(hx - MathF.Abs(point.X), hz - MathF.Abs(point.Y));
                    if (d <= 0f)
                    {
                        return new DistanceResult(0f, point, point);
                    }

                    Vector2 on = hx - MathF.Abs(point.X) <= hz - MathF.Abs(point.Y)
                        ? new Vector2(MathF.CopySign(hx, point.X), point.Y)
                        : new Vector2(point.X, MathF.CopySign(hz, point.Y));
                    return new DistanceResult(d, on, point);
                }

                default:
                    return ShapeQuery.Distance(ShapeOf(index), point);
            }
        }

        private static Vector2 Extreme(in Shape shape, Vector2 direction) => shape.Kind switch
        {
            ShapeKind.Circle => shape.AsCircle().Center + (shape.AsCircle().Radius * direction),
            ShapeKind.Segment => Vector2.Dot(shape.AsSegment().A, direction) >= Vector2.Dot(shape.AsSegment().B, direction) ? shape.AsSegment().A : shape.AsSegment().B,
            ShapeKind.Aabb => new Vector2(direction.X >= 0f ? shape.AsAabb().Max.X : shape.AsAabb().Min.X, direction.Y >= 0f ? shape.AsAabb().Max.Y : shape.AsAabb().Min.Y),
            ShapeKind.KDop8 => Farthest(shape.AsKDop8().Vertices, direction),
            _ => Farthest(shape.AsPolygon().Vertices, direction),
        };

        private static Vector2 Farthest(ReadOnlySpan<Vector2> points, Vector2 direction)
        {
            Vector2 best = points[0];
            foreach (Vector2 p in points)
            {
                if (Vector2.Dot(p, direction) > Vector2.Dot(best, direction))
                {
                    best = p;
                }
            }

            return best;
        }

        // The walls by hand: from inside the pool (or its edge), the ray leaves it where it first reaches an edge line.
        private RayCastResult WallsRay(Vector2 from, Vector2 to)
        {
            float hx = Field.Length / 2f, hz = Field.Width / 2f;
            if (from == to || MathF.Abs(from.X) > hx || MathF.Abs(from.Y) > hz)
            {
                return RayCastResult.Miss;
            }

            // A box twice the pool's size with the pool as a hole is not a library shape: cast
            // against each of the four edges as a thin box just outside the pool instead.
            RayCastResult best = RayCastResult.Miss;
            Shape[] sides =
            [
                new Aabb(new Vector2(hx, -hz - 1f), new Vector2(hx + 1e4f, hz + 1f)),
                new Aabb(new Vector2(-hx - 1e4f, -hz - 1f), new Vector2(-hx, hz + 1f)),
                new Aabb(new Vector2(-hx - 1f, hz), new Vector2(hx + 1f, hz + 1e4f)),
                new Aabb(new Vector2(-hx - 1f, -hz - 1e4f), new Vector2(hx + 1f, -hz)),
            ];
            foreach (Shape side in sides)
            {
                RayCastResult hit = ShapeQuery.RayCast(side, from, to);
                if (hit.Hit && (!best.Hit || hit.Fraction < best.Fraction))
                {
                    best = hit;
                }
            }

            return best;
        }

        private Shape ShapeOf(int index)
        {
            BodyId id = World.IdAt(index);
            if (_radii.TryGetValue(index, out float radius))
            {
                return new Circle(World.PositionOf(id), radius);
            }

            if (_polygons.TryGetValue(index, out ConvexPolygon local))
            {
                var (sin, cos) = MathF.SinCos(World.HeadingOf(id));
                Vector2 p = World.PositionOf(id);
                var world = new Vector2[local.Vertices.Length];
                for (int k = 0; k < world.Length; k++)
                {
                    Vector2 v = local.Vertices[k];
                    world[k] = p + new Vector2((v.X * cos) - (v.Y * sin), (v.X * sin) + (v.Y * cos));
                }

                return new ConvexPolygon(world);
            }

            return _statics[index];
        }
    }
}
