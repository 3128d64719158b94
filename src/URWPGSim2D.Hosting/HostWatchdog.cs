namespace URWPGSim2D.Hosting;

/// <summary>
/// One background thread that kills the strategy hosts that do not answer in time: a host is armed
/// with a deadline before the server waits for it and disarmed when its answer has come
/// (<see cref="HostProcess.BeginWait"/>), a few writes of numbers, so a cycle costs no timer operation
/// and no wake-up of another thread. The thread looks at the armed hosts every
/// <see cref="Period"/>; the limits it enforces are seconds long. A busy machine does not make a host
/// late: past its deadline a host is killed only when it is <see cref="Overdue"/>.
/// </summary>
internal static class HostWatchdog
{
    /// <summary>How often the armed hosts are looked at.</summary>
    public static readonly TimeSpan Period = TimeSpan.FromMilliseconds(25);

    /// <summary>How many times its limit in wall time a host is waited for at most, however long it waited for a CPU (<see cref="Overdue"/>).</summary>
    public const int Backstop = 5;

    /// <summary>
    /// Whether a host that has not answered after <paramref name="wall"/> of wall time is overdue for
    /// a wait of <paramref name="limit"/>: the time it waited for a CPU while runnable (a busy
    /// machine's doing, <paramref name="stalled"/>) does not count, but its sandbox's CPU time
    /// (<paramref name="cpu"/>) past the limit does, and so does any wall time past
    /// <see cref="Backstop"/> times the limit.
    /// </summary>
    /// <param name="wall">Wall time since the wait began.</param>
    /// <param name="limit">The wait's limit.</param>
    /// <param name="stalled">Of <paramref name="wall"/>, how long the host's sandbox was ready to run but waited for a CPU, or null where that is not measured.</param>
    /// <param name="cpu">The CPU time its sandbox used since the wait began, or null where that is not measured.</param>
    public static bool Overdue(TimeSpan wall, TimeSpan limit, TimeSpan? stalled, TimeSpan? cpu) =>
        wall > limit && (wall > limit * Backstop || cpu > limit || wall - (stalled is { } s && s > TimeSpan.Zero ? s : TimeSpan.Zero) > limit);

    private static readonly List<HostProcess> Hosts = [];
    private static Thread? _thread;

    /// <summary>Watches <paramref name="host"/> until <see cref="Forget"/>.</summary>
    public static void Watch(HostProcess host)
    {
        lock (Hosts)
        {
            Hosts.Add(host);
            if (_thread is null)
            {
                _thread = new Thread(Run) { IsBackground = true, Name = "strategy host watchdog" };
                _thread.Start();
            }
        }
    }

    /// <summary>Stops watching <paramref name="host"/>.</summary>
    public static void Forget(HostProcess host)
    {
        lock (Hosts)
        {
            Hosts.Remove(host);
        }
    }

    private static void Run()
    {
        var late = new List<HostProcess>();
        while (true)
        {
            Thread.Sleep(Period);
            long now = Environment.TickCount64;
            lock (Hosts)
            {
                foreach (var host in Hosts)
                {
                    if (host.IsLate(now))
                    {
                        late.Add(host);
                    }
                }
            }

            foreach (var host in late)
            {
                host.Kill(byWatchdog: true);
            }

            late.Clear();
        }
    }
}
