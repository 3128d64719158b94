namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// A step allocates nothing once warmed up, with the library alone: a pool with walls and goal
/// blocks, fish, balls, polygons and obstacles (a fifth of the bodies each), at 100, 1,000 and
/// 10,000 bodies, balls at up to 2,000 mm/s.
/// </summary>
public sealed class MotionWorldAllocationTests
{
    [Theory]
    [InlineData(100, 60, 20, 0)]
    [InlineData(1_000, 30, 10, 0)]
    [InlineData(10_000, 10, 4, 0)]
    [InlineData(1_000, 30, 10, 4)]
    public void AStepAllocatesNothingAfterWarmUp(int bodies, int warmUp, int steps, int heldSubSteps)
    {
        var world = World(bodies);
        world.HeldSubSteps = heldSubSteps;
        var handler = new RecordingHandler(0.3f) { Record = false };
        for (int i = 0; i < warmUp; i++)
        {
            world.Step(0.1f, handler);
        }

        // Up to three windows of the same length: a step that allocates fails every window; a
        // one-off allocation of the runtime's (seen a few times in full parallel test runs, never
        // alone) fails only the window it falls in.
        var windows = new long[3];
        for (int w = 0; w < windows.Length; w++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < steps; i++)
            {
                world.Step(0.1f, handler);
            }

            windows[w] = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.True(world.Events > 0, "no contact: the scene does not exercise the motion world");
            Assert.True(heldSubSteps == 0 || world.HeldAnswers > 0, "no held answer: the scene does not exercise held contacts");
            if (windows[w] == 0L)
            {
                return;
            }
        }

        Assert.Fail($"{bodies} bodies: {string.Join(", ", windows)} B in three windows of {steps} steps after warm-up");
    }

    // Bodies on a jittered lattice (no overlaps) in a pool whose area grows with their number.
    internal static MotionWorld World(int bodies)
    {
        float scale = MathF.Sqrt(bodies / 60f);
        var field = new Field(MathF.Max(3000f, 3000f * scale), MathF.Max(2000f, 2000f * scale));
        var world = new MotionWorld();
        world.AddWalls(field);
        foreach (Aabb block in field.GoalBlocks)
        {
            world.AddStatic(block);
        }

        var random = new Random(bodies);
        int columns = (int)MathF.Ceiling(MathF.Sqrt(bodies * 1.5f));
        int rows = (bodies + columns - 1) / columns;
        float dx = (field.Length - 700f) / columns, dz = (field.Width - 400f) / rows;
        var square = new ConvexPolygon([new Vector2(-30f, -20f), new Vector2(30f, -20f), new Vector2(30f, 20f), new Vector2(-30f, 20f)]);
        for (int i = 0; i < bodies; i++)
        {
            Vector2 at = new((-field.Length / 2f) + 350f + ((i % columns) + 0.5f) * dx, (-field.Width / 2f) + 200f + ((i / columns) + 0.5f) * dz);
            at += new Vector2((float)(random.NextDouble() - 0.5) * 10f, (float)(random.NextDouble() - 0.5) * 10f);
            float heading = (float)(random.NextDouble() * 2 * Math.PI);
            Vector2 velocity = new((float)(random.NextDouble() - 0.5) * 4000f, (float)(random.NextDouble() - 0.5) * 4000f);
            switch (i % 5)
            {
                case 0:
                    BodyId fish = world.AddFish(FishSize.Default, new FishPose(at, heading, 0.1f, -0.1f, 0.2f));
                    world.SetVelocity(fish, 300f * new Vector2(MathF.Cos(heading), MathF.Sin(heading)), 0.3f);
                    break;
                case 1:
                    BodyId polygon = world.AddPolygon(square, at, heading);
                    world.SetVelocity(polygon, velocity * 0.2f, 1f);
                    break;
                case 2:
                    world.AddStatic(new Circle(at, 25f));
                    break;
                default:
                    BodyId ball = world.AddCircle(38f, at);
                    world.SetVelocity(ball, velocity * 0.5f);
                    break;
            }
        }

        return world;
    }
}
