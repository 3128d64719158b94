using System;
using URWPGSim2D.Server.Scenario;
using Xunit;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// A crowded cycle allocates nothing once warmed up: the crowd scene of 100, 1,000 and 10,000
/// fish and balls (the scaling benchmark's scene), measured over the cycles after the first 20.
/// </summary>
public sealed class CrowdAllocationTests
{
    [Theory]
    [InlineData(100, 40)]
    [InlineData(1_000, 20)]
    [InlineData(10_000, 6)]
    public void ACrowdCycleAllocatesNothingAfterWarmUp(int objects, int cycles)
    {
        var match = MatchBuilder.Build(CrowdScenario.Create(objects));
        match.Play(20);
        // Up to three windows of the same length: a cycle that allocates fails every window; a
        // one-off allocation of the runtime's (seen a few times in full parallel test runs, never
        // alone) fails only the window it falls in.
        var windows = new long[3];
        for (int w = 0; w < windows.Length; w++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            match.Play(cycles);
            windows[w] = GC.GetAllocatedBytesForCurrentThread() - before;
            if (windows[w] == 0L)
            {
                return;
            }
        }

        Assert.Fail($"{objects} bodies: {string.Join(", ", windows)} B in three windows of {cycles} cycles after warm-up");
    }
}
