namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// Islands and <see cref="MotionWorld.Threads"/>: the islands agree with brute force (two movers whose
/// swept circles meet are in one island), and a crowd stepped on 1, 2, 3 or 4 threads ends every
/// step with the same poses, velocities, contacts (in order) and counts, bit for bit.
/// </summary>
public sealed class MotionWorldIslandTests
{
    private const float Seconds = 0.1f;

    [Fact]
    public void MoversWhoseSweptCirclesMeetShareAnIsland()
    {
        var world = MotionWorldAllocationTests.World(600);
        world.Threads = 2; // islands are then found at the start of every step (one thread finds them only at a first hit)
        world.MinimumMoversForThreads = 64;
        var handler = new RecordingHandler(0.3f) { Record = false };
        for (int step = 0; step < 4; step++)
        {
            // Each mover's swept circle from its state at the start of the step, computed here from
            // the definition (bounding circle grown by the most any of its points moves in the step).
            var movers = new List<BodyId>();
            var circles = new List<(Vector2 Center, float Radius)>();
            for (int id = 0; id < world.BodyCount; id++)
            {
                if (world.KindOf(world.IdAt(id)) > BodyKind.Fish)
                {
                    continue;
                }

                Body body = world.BodyAt(id);
                Disc bound = body.Bound();
                float reach = body.Kind == BodyKind.Circle ? 0f : Vector2.Distance(bound.Center, body.Position) + bound.Radius;
                float travel = (body.Velocity.Length() * Seconds) + (MathF.Abs(body.AngularVelocity) * reach * Seconds);
                movers.Add(world.IdAt(id));
                circles.Add((bound.Center, bound.Radius + travel));
            }

            world.Step(Seconds, handler);
            int joined = 0;
            for (int i = 0; i < movers.Count; i++)
            {
                for (int j = i + 1; j < movers.Count; j++)
                {
                    float reach = circles[i].Radius + circles[j].Radius + 1f; // the planner's 1 mm margin
                    if (Vector2.DistanceSquared(circles[i].Center, circles[j].Center) < reach * reach)
                    {
                        joined++;
                        Assert.True(
                            world.IslandOf(movers[i]) == world.IslandOf(movers[j]),
                            $"step {step}: bodies {movers[i]} and {movers[j]} can meet but are in islands {world.IslandOf(movers[i])} and {world.IslandOf(movers[j])}");
                    }
                }
            }

            Assert.True(joined > 10, $"step {step}: only {joined} pairs can meet: the scene does not test islands");
            Assert.InRange(world.IslandCount, 2, movers.Count - 1);
        }
    }

    [Fact]
    public void OneThreadFindsTheSameIslandsAtItsFirstHit()
    {
        // One thread finds the islands only when a step's first sample with a hit needs them, from
        // the pairs planned at the start of the step; two threads find them first thing. Stepped side by side.
        var one = MotionWorldAllocationTests.World(600);
        var two = MotionWorldAllocationTests.World(600);
        two.Threads = 2;
        two.MinimumMoversForThreads = 64;
        var handlerOne = new RecordingHandler(0.3f) { Record = false };
        var handlerTwo = new RecordingHandler(0.3f) { Record = false };
        int compared = 0;
        for (int step = 0; step < 4; step++)
        {
            one.Step(Seconds, handlerOne);
            two.Step(Seconds, handlerTwo);
            Assert.Equal(1, one.Chunks);
            Assert.Equal(2, two.Chunks);
            if (one.IslandCount < 0)
            {
                continue;
            }

            compared++;
            Assert.Equal(two.IslandCount, one.IslandCount);
            for (int id = 0; id < one.BodyCount; id++)
            {
                if (one.KindOf(one.IdAt(id)) <= BodyKind.Fish)
                {
                    Assert.True(one.IslandOf(one.IdAt(id)) == two.IslandOf(two.IdAt(id)), $"step {step}: body {id} in island {one.IslandOf(one.IdAt(id))} on one thread, {two.IslandOf(two.IdAt(id))} on two");
                }
            }
        }

        Assert.True(compared > 0, "no step had a hit before its event loop: the islands of one thread were not compared");
    }

    [Fact]
    public void EveryThreadCountGivesTheSameSteps()
    {
        var reference = Run(1, out var referenceContacts, out int oneChunk);
        Assert.Equal(1, oneChunk);
        Assert.True(referenceContacts.Count > 100, $"only {referenceContacts.Count} contacts: the scene does not exercise the motion world");
        foreach (int threads in new[] { 2, 3, 4 })
        {
            var other = Run(threads, out var contacts, out int chunks);
            Assert.Equal(threads, chunks);
            Assert.Equal(reference.Count, other.Count);
            for (int i = 0; i < reference.Count; i++)
            {
                Assert.True(reference[i] == other[i], $"{threads} threads: state line {i} differs: {reference[i]} against {other[i]}");
            }

            Assert.Equal(referenceContacts.Count, contacts.Count);
            for (int i = 0; i < contacts.Count; i++)
            {
                Assert.True(Same(referenceContacts[i], contacts[i]), $"{threads} threads: contact {i} differs");
            }
        }
    }

    [Theory]
    [InlineData(0)]
    [InlineData(-3)]
    [InlineData(1025)]
    public void ThreadsOutOfRangeAreRejected(int threads)
    {
        var world = new MotionWorld();
        var e = Assert.Throws<ArgumentException>(() => world.Threads = threads);
        Assert.Contains($"got {threads}", e.Message, StringComparison.Ordinal);
        Assert.Equal(1, world.Threads);
    }

    // 12 steps of a 1,000-body crowd (about 600 movers): per step the counts, per mover its exact state.
    internal static List<string> Run(int threads, out List<Contact> contacts, out int chunks, int heldSubSteps = 0)
    {
        var world = MotionWorldAllocationTests.World(1_000);
        world.HeldSubSteps = heldSubSteps;
        world.Threads = threads;
        world.MinimumMoversForThreads = 64; // below the default, so that a test-sized crowd uses the threads
        var handler = new RecordingHandler(0.3f);
        var lines = new List<string>();
        chunks = 0;
        for (int step = 0; step < 12; step++)
        {
            world.Step(Seconds, handler);
            chunks = Math.Max(chunks, world.Chunks);
            lines.Add($"step {step}: sub-steps {world.SubSteps}, events {world.Events}, held answers {world.HeldAnswers}, rejected {world.RejectedMoves}, overlap {Bits(world.LeftoverOverlap)}");
            for (int id = 0; id < world.BodyCount; id++)
            {
                if (world.KindOf(world.IdAt(id)) <= BodyKind.Fish)
                {
                    Vector2 p = world.PositionOf(world.IdAt(id)), v = world.VelocityOf(world.IdAt(id));
                    lines.Add($"{id}: {Bits(p.X)} {Bits(p.Y)} {Bits(world.HeadingOf(world.IdAt(id)))} {Bits(v.X)} {Bits(v.Y)} {Bits(world.AngularVelocityOf(world.IdAt(id)))}");
                }
            }
        }

        contacts = handler.Contacts;
        return lines;
    }

    internal static bool Same(in Contact a, in Contact b) =>
        a.BodyA.Index == b.BodyA.Index && a.BodyB.Index == b.BodyB.Index && a.Time == b.Time
        && a.Result.MinimumTranslationVector == b.Result.MinimumTranslationVector
        && a.Result.NormalAxis == b.Result.NormalAxis && a.Result.ActionPoint == b.Result.ActionPoint;

    private static int Bits(float value) => BitConverter.SingleToInt32Bits(value);
}
