using System;
using System.Diagnostics;
using System.Runtime.InteropServices;
using System.Threading;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// The deadline clock of a real match: the CPU time of the strategy's thread (Linux:
/// <c>pthread_getcpuclockid</c>; elsewhere wall time), so time the machine spends on other work does not
/// count. A call that does not run (it sleeps or blocks) is also given up after
/// <see cref="HangLimitFor"/> its deadline in wall time (ten deadlines, at least a second); its answer,
/// should it come, is discarded.
/// </summary>
internal sealed partial class ThreadTimeClock : StrategyClock
{
    private const int ThreadCpuClockFailed = int.MinValue;
    private const int ProcessCpuClock = 2; // CLOCK_PROCESS_CPUTIME_ID: every thread of the process
    private readonly bool _wholeProcess;

    private readonly Stopwatch _wall = new();
    private int _clockId = ThreadCpuClockFailed;
    private long _startNs;

    /// <summary>A clock of the strategy's own thread (a strategy in the server's process, or on a remote team's machine).</summary>
    public ThreadTimeClock()
    {
    }

    /// <summary>
    /// A clock of the strategy's thread, or with <paramref name="wholeProcess"/> of every thread of this
    /// process (a strategy host, which runs one strategy: threads it starts count against its deadline too).
    /// </summary>
    public ThreadTimeClock(bool wholeProcess) => _wholeProcess = wholeProcess;

    /// <summary>Wall time after which an unfinished call is given up whatever its CPU time: ten deadlines, at least one second.</summary>
    /// <param name="deadline">The per-call deadline.</param>
    public static TimeSpan HangLimitFor(TimeSpan deadline) => TimeSpan.FromTicks(Math.Max(TimeSpan.TicksPerSecond, deadline.Ticks * 10));

    /// <inheritdoc/>
    public override void CallStarting()
    {
        if (_clockId == ThreadCpuClockFailed && OperatingSystem.IsLinux() && _wholeProcess)
        {
            _clockId = ProcessCpuClock;
        }
        else if (_clockId == ThreadCpuClockFailed && OperatingSystem.IsLinux())
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
    public override TimeSpan CallEnded() => TimeSpan.FromTicks((Now() - Volatile.Read(ref _startNs)) / 100);

    /// <inheritdoc/>
    public override bool WaitForCall(SemaphoreSlim done, TimeSpan budget)
    {
        int slice = (int)Math.Clamp(budget.TotalMilliseconds / 4, 1, 50);
        while (!done.Wait(slice))
        {
            long used = Now() - Volatile.Read(ref _startNs);
            if (used > budget.Ticks * 100 || _wall.Elapsed > HangLimitFor(budget))
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
