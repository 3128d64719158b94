namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// A step on two threads allocates nothing once warmed up, on the calling thread or on the island
/// workers' threads (each worker counts its own thread's bytes after every chunk).
/// </summary>
public sealed class MotionWorldThreadAllocationTests
{
    [Theory]
    [InlineData(1_000, 20, 10)]
    [InlineData(10_000, 6, 3)]
    public void AStepOnTwoThreadsAllocatesNothingAfterWarmUp(int bodies, int warmUp, int steps)
    {
        var world = MotionWorldAllocationTests.World(bodies);
        world.Threads = 2;
        world.MinimumMoversForThreads = 64; // so that 1,000 bodies use the threads too
        var handler = new RecordingHandler(0.3f) { Record = false };
        for (int i = 0; i < warmUp; i++)
        {
            world.Step(0.1f, handler);
        }

        // Up to three windows (a one-off allocation of the runtime's fails only the window it falls in).
        var windows = new long[3];
        for (int w = 0; w < windows.Length; w++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread() + world.WorkerAllocatedBytes;
            for (int i = 0; i < steps; i++)
            {
                world.Step(0.1f, handler);
            }

            windows[w] = GC.GetAllocatedBytesForCurrentThread() + world.WorkerAllocatedBytes - before;
            Assert.True(world.Events > 0, "no contact: the scene does not exercise the motion world");
            Assert.True(world.Chunks == 2, $"{world.Chunks} chunk(s) of {world.IslandCount} islands: the step did not use two threads");
            if (windows[w] == 0L)
            {
                return;
            }
        }

        Assert.Fail($"{bodies} bodies on 2 threads: {string.Join(", ", windows)} B in three windows of {steps} steps after warm-up");
    }
}
