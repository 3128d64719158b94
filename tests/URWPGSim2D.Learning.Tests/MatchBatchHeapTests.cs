namespace URWPGSim2D.Learning.Tests;

/// <summary>
/// What a batch's matches hold on the heap. The heap is measured after full collections, which
/// count every live object of the process, so these tests run alone: in a collection that is not
/// run beside any other test of this assembly.
/// </summary>
[Collection(HeapCollection.Name)]
public sealed class MatchBatchHeapTests
{
    [Fact]
    public void AMatchHoldsUnder90KilobytesAfterResetAndUnder128AfterItsFirstBusySteps()
    {
        // What the heap holds after a full collection, before the batch and with it: its matches
        // after reset, then after the first steps (which size the motion world's buffers).
        const int count = 64;
        var warm = new MatchBatch("polo-1v1", "chase-ball", 2, 0, 6000);
        warm.Reset([1, 2], new float[2 * warm.ObservationSize]);
        var seeds = new ulong[count];
        var actions = new int[count * 2];
        var rewards = new float[count];
        var terminated = new bool[count];
        var truncated = new bool[count];
        for (int i = 0; i < count; i++)
        {
            seeds[i] = (ulong)i;
            actions[2 * i] = 12; // full speed ahead, into the walls and goal blocks: contacts every cycle
            actions[(2 * i) + 1] = (i % 3) + 6;
        }

        long before = GC.GetTotalMemory(forceFullCollection: true);
        var batch = new MatchBatch("polo-1v1", "chase-ball", count, 0, 6000);
        var obs = new float[count * batch.ObservationSize];
        batch.Reset(seeds, obs);
        long reset = GC.GetTotalMemory(forceFullCollection: true) - before;
        for (int step = 0; step < 300; step++)
        {
            batch.Step(actions, obs, rewards, terminated, truncated);
        }

        long stepped = GC.GetTotalMemory(forceFullCollection: true) - before;
        GC.KeepAlive(batch);
        Assert.True(reset < count * 90 * 1024, $"{reset / count} B a match after reset");
        Assert.True(stepped < count * 128 * 1024, $"{stepped / count} B a match after 300 steps");
    }
}

/// <summary>Tests that measure the whole heap: not run in parallel with the other tests.</summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class HeapCollection
{
    /// <summary>The collection's name.</summary>
    public const string Name = "heap";
}
