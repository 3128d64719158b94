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
        long before = GC.GetAllocatedBytesForCurrentThread();
        match.Play(cycles);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.True(allocated == 0L, $"{objects} bodies: {allocated} B in {cycles} cycles after warm-up");
    }
}
