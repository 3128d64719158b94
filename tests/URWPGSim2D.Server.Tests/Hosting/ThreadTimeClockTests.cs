namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>The real deadline clock counts the strategy thread's CPU time, not wall time.</summary>
public sealed class ThreadTimeClockTests
{
    [Fact]
    public void ASleepingCallUsesAlmostNoTime()
    {
        Assert.True(OperatingSystem.IsLinux(), "the thread CPU clock is Linux's; CI runs on Linux");
        var clock = new ThreadTimeClock();
        clock.CallStarting();
        Thread.Sleep(300);
        (TimeSpan used, TimeSpan wall) = clock.CallEnded();
        Assert.True(used < TimeSpan.FromMilliseconds(150), $"a 300 ms sleep used {used.TotalMilliseconds} ms of CPU");
        Assert.True(wall >= TimeSpan.FromMilliseconds(300), $"a 300 ms sleep took {wall.TotalMilliseconds} ms of wall time");
    }

    [Fact]
    public void TheHangLimitIsTenDeadlinesAndAtLeastASecond()
    {
        Assert.Equal(TimeSpan.FromSeconds(1), ThreadTimeClock.HangLimitFor(TimeSpan.FromMilliseconds(20)));
        Assert.Equal(TimeSpan.FromSeconds(5), ThreadTimeClock.HangLimitFor(TimeSpan.FromMilliseconds(500)));
    }
}
