namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The motion world's memo of exact tests answers a repeated test exactly as the test itself does, and
/// never answers from a stale test: over random poses of fish, balls, a moving polygon, static
/// bodies and the walls, each pair is asked again unchanged (answered from the memo), after a move
/// of either body, after a fish's joints change, and after other pairs pushed it out of its entry.
/// </summary>
public sealed class TestMemoTests
{
    private const int Trials = 600;

    [Theory]
    [InlineData(0)] // the 128 entries of a small world
    [InlineData(1_000)] // a crowd's 1,024 entries
    public void RepeatedTestsAnswerAsTheTestAndChangesAreNeverMissed(int movers)
    {
        var random = new Random(77);
        var field = new Field();
        var square = new ConvexPolygon([new Vector2(-40f, -25f), new Vector2(40f, -25f), new Vector2(40f, 25f), new Vector2(-40f, 25f)]);
        Body[] bodies =
        [
            Body.Fish(0, FishSize.Default, new FishPose(Vector2.Zero, 0f)),
            Body.Fish(1, FishSize.Default, new FishPose(new Vector2(200f, 0f), 0f)),
            Body.Circle(2, 58f, Vector2.Zero),
            Body.Circle(3, 38f, Vector2.Zero),
            Body.Polygon(4, square, Vector2.Zero, 0f),
            Body.Static(5, new Circle(new Vector2(0f, 60f), 58f)),
            Body.Static(6, field.GoalBlocks[0]),
            Body.Walls(7, field),
        ];
        var memo = new TestMemo();
        if (movers > 0)
        {
            memo.Reserve(movers);
        }
        int overlapping = 0;
        for (int trial = 0; trial < Trials; trial++)
        {
            try
            {
                Vector2 centre = new(((float)random.NextDouble() - 0.5f) * 2600f, ((float)random.NextDouble() - 0.5f) * 1600f);
                for (int i = 0; i < 5; i++)
                {
                    Place(random, bodies[i], centre);
                }

                for (int a = 0; a < 5; a++)
                {
                    for (int b = a + 1; b < bodies.Length; b++)
                    {
                        Hit first = memo.Detect(bodies[a], bodies[b]);
                        Same(PairTest.Detect(bodies[a], bodies[b]), first);
                        Same(first, memo.Detect(bodies[a], bodies[b]));
                        overlapping += first.Intersect ? 1 : 0;
                    }
                }

                // A move of A, a move of B, a joint change: the memo tests again.
                Body fish = bodies[0];
                Body other = bodies[1 + random.Next(4)];
                memo.Detect(fish, other);
                fish.Position += new Vector2(0.5f, -0.25f);
                fish.Invalidate();
                Same(PairTest.Detect(fish, other), memo.Detect(fish, other));
                other.Position -= new Vector2(0.75f, 0.5f);
                other.Invalidate();
                Same(PairTest.Detect(fish, other), memo.Detect(fish, other));
                fish.Joint3 += 0.3f;
                fish.ShapeStamp++;
                fish.Invalidate();
                Same(PairTest.Detect(fish, other), memo.Detect(fish, other));
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(77, trial, e);
            }
        }

        Assert.True(overlapping > 500, $"only {overlapping} overlapping pairs were tested");
    }

    [Fact]
    public void ItCountsTheTestsItRunsAndHandsTheCountOn()
    {
        var field = new Field();
        Body ball = Body.Circle(0, 58f, new Vector2(100f, 0f));
        Body post = Body.Static(1, new Circle(Vector2.Zero, 50f));
        Body walls = Body.Walls(2, field);
        var memo = new TestMemo();
        memo.Detect(ball, post);
        memo.Detect(ball, post); // remembered
        memo.Detect(ball, walls);
        Assert.Equal(2, memo.Tests);

        // A worker's count joins the event loop's and starts again from 0.
        var worker = new TestMemo();
        worker.Detect(ball, post); // its own memory: tested
        memo.TakeTests(worker);
        Assert.Equal(3, memo.Tests);
        Assert.Equal(0, worker.Tests);

        memo.ResetTests();
        Assert.Equal(0, memo.Tests);
        memo.Detect(ball, post); // still remembered: the count is of tests run, the memory stays
        Assert.Equal(0, memo.Tests);
    }

    private static void Same(in Hit expected, in Hit actual)
    {
        Assert.Equal(expected.Intersect, actual.Intersect);
        Assert.Equal(expected.Depth, actual.Depth, 1e-4f);
        Assert.True(Vector2.Distance(expected.Mtv, actual.Mtv) < 1e-4f, $"MTV {actual.Mtv} instead of {expected.Mtv}");
        Assert.True(Vector2.Distance(expected.Point, actual.Point) < 1e-3f, $"action point {actual.Point} instead of {expected.Point}");
        Assert.Equal(expected.PartA, actual.PartA);
        Assert.Equal(expected.PartB, actual.PartB);
    }

    private static void Place(Random random, Body body, Vector2 around)
    {
        body.Position = around + new Vector2(((float)random.NextDouble() - 0.5f) * 500f, ((float)random.NextDouble() - 0.5f) * 500f);
        if (body.Kind != BodyKind.Circle)
        {
            body.Heading = (float)((random.NextDouble() * 2.0 * Math.PI) - Math.PI);
        }

        if (body.Kind == BodyKind.Fish)
        {
            body.Joint1 = ((float)random.NextDouble() - 0.5f) * 0.6f;
            body.Joint2 = ((float)random.NextDouble() - 0.5f) * 0.6f;
            body.Joint3 = ((float)random.NextDouble() - 0.5f) * 0.6f;
            body.ShapeStamp++;
        }

        body.Invalidate();
    }
}
