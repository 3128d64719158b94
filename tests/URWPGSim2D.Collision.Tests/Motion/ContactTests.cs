namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>A contact's plane view (translation, normal, point, depth) against the analytic overlap and its own result.</summary>
public sealed class ContactTests
{
    [Fact]
    public void TwoBallsOverlappingAlongADiagonal()
    {
        var world = new MotionWorld();
        BodyId a = world.AddCircle(50f, new Vector2(0f, 0f));
        BodyId b = world.AddCircle(50f, new Vector2(60f, 80f)); // centres 100 mm apart: touching
        world.SetPose(a, new Vector2(6f, 8f), 0f);          // now 90 mm apart: 10 mm deep along (−0.6, −0.8)

        Contact c = world.Detect(a, b);

        Assert.True(c.Intersect);
        Assert.Equal(10f, c.Depth, 1e-3f);
        Assert.Equal(-0.6f, c.Normal.X, 1e-4f);
        Assert.Equal(-0.8f, c.Normal.Y, 1e-4f);
        Assert.Equal(-6f, c.Mtv.X, 1e-3f);
        Assert.Equal(-8f, c.Mtv.Y, 1e-3f);
        Assert.Null(c.PartA);
        Assert.Null(c.PartB);
    }

    [Fact]
    public void ThePlaneViewIsTheResultsAndTheDepthItsTranslationsLength()
    {
        var random = new Random(5);
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f));
        BodyId ball = world.AddCircle(58f, new Vector2(1000f, 0f));
        int hits = 0;
        for (int i = 0; i < 2_000; i++)
        {
            world.SetPose(fish, Vector2.Zero, (float)((random.NextDouble() * 6.2) - 3.1));
            world.SetPose(ball, new Vector2((float)((random.NextDouble() * 800) - 400), (float)((random.NextDouble() * 300) - 150)), 0f);
            Contact c = world.Detect(fish, ball);
            CollisionDetectionResult r = c.Result;
            if (!c.Intersect)
            {
                Assert.Equal(0f, c.Depth);
                Assert.Equal(Vector2.Zero, c.Mtv);
                continue;
            }

            hits++;
            Assert.Equal(new Vector2(r.MinimumTranslationVector.X, r.MinimumTranslationVector.Z), c.Mtv);
            Assert.Equal(new Vector2(r.NormalAxis.X, r.NormalAxis.Z), c.Normal);
            Assert.Equal(new Vector2(r.ActionPoint.X, r.ActionPoint.Z), c.Point);
            Assert.Equal(c.Mtv.Length(), c.Depth);
            Assert.NotNull(c.PartA);
        }

        Assert.InRange(hits, 100, 1_900); // both outcomes were exercised
    }
}
