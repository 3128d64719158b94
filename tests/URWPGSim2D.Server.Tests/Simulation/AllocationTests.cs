namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>The hot cycle allocates nothing once warmed up (default match, built-in strategies).</summary>
public sealed class AllocationTests
{
    [Fact]
    public void ACycleOfTheDefaultMatchAllocatesNothingAfterWarmUp()
    {
        var match = MatchBuilder.Build(DefaultScenario.Load());
        match.Play(300);
        long before = GC.GetAllocatedBytesForCurrentThread();
        match.Play(300);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal(0L, allocated);
    }
}
