namespace URWPGSim2D.Hosting;

/// <summary>
/// One background thread that kills the strategy hosts that do not answer in time: a host is armed
/// with a deadline before the server waits for it and disarmed when its answer has come
/// (<see cref="HostProcess.BeginWait"/>), two writes of a number, so a cycle costs no timer operation and
/// no wake-up of another thread. The thread looks at the armed hosts every
/// <see cref="Period"/>; the limits it enforces are seconds long.
/// </summary>
internal static class HostWatchdog
{
    /// <summary>How often the armed hosts are looked at.</summary>
    public static readonly TimeSpan Period = TimeSpan.FromMilliseconds(25);

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
