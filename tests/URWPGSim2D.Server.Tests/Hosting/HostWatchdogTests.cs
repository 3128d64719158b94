namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// When the watchdog kills a host that has not answered (<see cref="HostWatchdog.Overdue"/>): past its
/// limit of the host's own time, never for time a busy machine kept it waiting for a CPU, yet a host
/// that computes (its sandbox's CPU time past the limit), sleeps or is stopped is killed at its limit,
/// and none is waited for beyond the backstop.
/// </summary>
public sealed class HostWatchdogTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(10);

    [Theory]
    [InlineData(9.9, 0.0, 9.9, false)] // within its limit, computing all along
    [InlineData(9.9, null, null, false)] // within its limit, nothing measured
    [InlineData(30.0, 25.0, 1.0, false)] // a busy machine: 25 s of the 30 waiting for a CPU, 1 s computed
    [InlineData(30.0, 20.5, 1.0, false)] // 9.5 s of its own time
    [InlineData(30.0, 19.5, 1.0, true)] // 10.5 s of its own time
    [InlineData(10.1, 0.0, 0.0, true)] // stopped or asleep: nothing waited for, nothing computed
    [InlineData(10.1, null, null, true)] // nothing measured: the wall time is its own
    [InlineData(10.1, null, 0.0, true)]
    [InlineData(12.0, 11.0, 12.0, true)] // many threads computing, each waiting for a CPU: its CPU time counts
    [InlineData(49.9, 49.9, 0.0, false)] // the machine kept it waiting all along, within the backstop
    [InlineData(50.1, 50.1, 0.0, true)] // past the backstop, five times its limit
    [InlineData(10.1, -1.0, null, true)] // a reading that went back counts as no wait
    public void A_host_past_its_limit_is_overdue_only_for_its_own_time(double wall, double? stalled, double? cpu, bool overdue)
    {
        Assert.Equal(overdue, HostWatchdog.Overdue(Seconds(wall), Limit, stalled is { } s ? Seconds(s) : null, cpu is { } c ? Seconds(c) : null));
    }

    [Fact]
    public void The_backstop_is_five_times_the_limit()
    {
        Assert.False(HostWatchdog.Overdue(TimeSpan.FromSeconds(5), TimeSpan.FromSeconds(1), TimeSpan.FromSeconds(5), TimeSpan.Zero));
        Assert.True(HostWatchdog.Overdue(TimeSpan.FromSeconds(5) + TimeSpan.FromTicks(1), TimeSpan.FromSeconds(1), TimeSpan.FromSeconds(5), TimeSpan.Zero));
    }

    private static TimeSpan Seconds(double s) => TimeSpan.FromSeconds(s);
}
