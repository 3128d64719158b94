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

    /// <summary>
    /// The buffers that grow with a cycle's pairs and contacts (the broad phase's pairs, the
    /// islands' pairs, the cycle's contact log) are sized for the world when it is loaded: the
    /// 1,000-body crowd, whose contacts multiply as its fish bunch up (more than 1,024 contacts in
    /// one cycle from cycle 998 on, up to 1,207 by cycle 1,200; near cycle 860 before the circle
    /// kernel's action points moved by rounding), allocates nothing from cycle 20 to cycle 1,200.
    /// Before they were sized up front, buffers grew at cycles 26, 90, 585 and 859 (2 KB, 8 KB,
    /// 4 KB and 112 KB).
    /// </summary>
    [Fact]
    public void ACrowdAllocatesNothingWhileItsContactsMultiply()
    {
        var match = MatchBuilder.Build(CrowdScenario.Create(1_000));
        match.Play(20);
        long before = GC.GetAllocatedBytesForCurrentThread();
        int most = 0;
        for (int cycle = 20; cycle < 1_200; cycle++)
        {
            match.Step();
            most = Math.Max(most, match.Contacts.Count);
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.True(most > 1_024, $"the scene no longer reaches a cycle of more than 1,024 contacts (most {most}): the test must find another busy stretch");
        Assert.Equal(0L, allocated);
    }
}
