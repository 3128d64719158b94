using System.Runtime.InteropServices;

namespace URWPGSim2D.Hosting;

/// <summary>
/// The clock of a real match: the CPU time of the strategy's thread (Linux:
/// <c>pthread_getcpuclockid</c>; elsewhere wall time), so time the machine spends on other work does not
/// count, and the call's wall time.
/// </summary>
internal sealed partial class ThreadTimeClock : StrategyClock
{
    private const int ThreadCpuClockFailed = int.MinValue;

    private readonly Stopwatch _wall = new();
    private int _clockId = ThreadCpuClockFailed;
    private long _startNs;

    /// <summary>Wall time a strategy's first call is allowed (its code is compiled then): ten deadlines, at least one second.</summary>
    /// <param name="deadline">The per-call deadline.</param>
    public static TimeSpan HangLimitFor(TimeSpan deadline) => TimeSpan.FromTicks(Math.Max(TimeSpan.TicksPerSecond, deadline.Ticks * 10));

    /// <inheritdoc/>
    public override void CallStarting()
    {
        if (_clockId == ThreadCpuClockFailed && OperatingSystem.IsLinux())
        {
            try
            {
                if (PthreadGetCpuClockId(PthreadSelf(), out int id) == 0)
                {
                    _clockId = id;
                }
            }
            catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
            {
                _clockId = ThreadCpuClockFailed;
            }
        }

        Volatile.Write(ref _startNs, Now());
        _wall.Restart();
    }

    /// <inheritdoc/>
    public override (TimeSpan Cpu, TimeSpan Wall) CallEnded() => (TimeSpan.FromTicks((Now() - Volatile.Read(ref _startNs)) / 100), _wall.Elapsed);

    /// <inheritdoc/>
    public override bool WaitForCall(SemaphoreSlim done, TimeSpan cpuLimit, TimeSpan wallLimit)
    {
        if (cpuLimit == Timeout.InfiniteTimeSpan && wallLimit == Timeout.InfiniteTimeSpan)
        {
            done.Wait();
            return true;
        }

        int slice = (int)Math.Clamp(Math.Min(cpuLimit.TotalMilliseconds, wallLimit.TotalMilliseconds) / 4, 1, 50);
        long cpuNs = cpuLimit == Timeout.InfiniteTimeSpan ? long.MaxValue : (long)Math.Min(cpuLimit.Ticks * 100.0, long.MaxValue / 2);
        var wall = Stopwatch.StartNew();
        while (!done.Wait(slice))
        {
            if (Now() - Volatile.Read(ref _startNs) > cpuNs || (wallLimit != Timeout.InfiniteTimeSpan && wall.Elapsed > wallLimit))
            {
                return false;
            }
        }

        return true;
    }

    // Nanoseconds of the strategy thread's CPU clock (readable from any thread), or of wall time.
    private long Now()
    {
        int id = Volatile.Read(ref _clockId);
        if (id != ThreadCpuClockFailed && ClockGetTime(id, out Timespec t) == 0)
        {
            return (t.Seconds * 1_000_000_000L) + t.Nanoseconds;
        }

        return (long)(Stopwatch.GetTimestamp() * (1e9 / Stopwatch.Frequency));
    }

    [LibraryImport("libc", EntryPoint = "pthread_self")]
    private static partial nuint PthreadSelf();

    [LibraryImport("libc", EntryPoint = "pthread_getcpuclockid")]
    private static partial int PthreadGetCpuClockId(nuint thread, out int clockId);

    [LibraryImport("libc", EntryPoint = "clock_gettime")]
    private static partial int ClockGetTime(int clockId, out Timespec time);

    [StructLayout(LayoutKind.Sequential)]
    private struct Timespec
    {
        public long Seconds;
        public long Nanoseconds;
    }
}
