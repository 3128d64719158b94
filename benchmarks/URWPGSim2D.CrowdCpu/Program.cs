using System;
using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using System.Threading;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Hosting;

namespace URWPGSim2D.CrowdCpu;

/// <summary>
/// One whole cycle of the crowd scene (<c>run --crowd N</c>: <see cref="CrowdScenario"/> through
/// <see cref="MatchBuilder"/>, the uniform grid, one thread) timed by the thread's CPU clock, so that
/// other work on the machine hardly moves it:
/// <c>URWPGSim2D.CrowdCpu N[,N...] WARM MEASURE</c> plays WARM cycles of each scene, then times
/// MEASURE cycles one by one, and prints <c>crowd N CPU_MS WALL_MS</c> per scene (the medians, ms).
/// </summary>
internal static partial class Program
{
    private const int ThreadCpuClock = 3; // CLOCK_THREAD_CPUTIME_ID (Linux)

    private static int Main(string[] args)
    {
        if (args.Length != 3 || !TryCounts(args[0], out int[] counts)
            || !int.TryParse(args[1], NumberStyles.None, CultureInfo.InvariantCulture, out int warm)
            || !int.TryParse(args[2], NumberStyles.None, CultureInfo.InvariantCulture, out int measure) || measure < 1)
        {
            Console.Error.WriteLine("usage: URWPGSim2D.CrowdCpu N[,N...] WARM MEASURE (N: fish and balls, at least 1; MEASURE at least 1)");
            return 2;
        }

        if (!OperatingSystem.IsLinux())
        {
            Console.Error.WriteLine("URWPGSim2D.CrowdCpu reads the thread's CPU clock of Linux");
            return 2;
        }

        WarmUp();
        foreach (int n in counts)
        {
            Match match = Build(n);
            for (int i = 0; i < warm; i++)
            {
                match.Step();
            }

            var cpu = new double[measure];
            var wall = new double[measure];
            for (int i = 0; i < measure; i++)
            {
                long w0 = Stopwatch.GetTimestamp();
                long c0 = CpuNs();
                match.Step();
                cpu[i] = (CpuNs() - c0) * 1e-6;
                wall[i] = Stopwatch.GetElapsedTime(w0).TotalMilliseconds;
            }

            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"crowd {n} {Median(cpu):F4} {Median(wall):F4}"));
        }

        return 0;
    }

    private static bool TryCounts(string text, out int[] counts)
    {
        string[] parts = text.Split(',');
        counts = new int[parts.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            if (!int.TryParse(parts[i], NumberStyles.None, CultureInfo.InvariantCulture, out counts[i]) || counts[i] < 1)
            {
                return false;
            }
        }

        return true;
    }

    private static Match Build(int n) =>
        MatchBuilder.Build(CrowdScenario.Create(n, 1UL, 3000), null, null, null, MatchBuilder.DefaultStrategyTimeoutMs, BroadPhaseKind.UniformGrid, null);

    // Two seconds of a throwaway 1,000-body match, so that the timed cycles run tier-1 code, then a
    // pause for the compiler's background thread to finish.
    private static void WarmUp()
    {
        Match match = Build(1000);
        var clock = Stopwatch.StartNew();
        while (clock.Elapsed.TotalSeconds < 2)
        {
            match.Step();
        }

        Thread.Sleep(500);
    }

    private static double Median(double[] values)
    {
        Array.Sort(values);
        int m = values.Length / 2;
        return values.Length % 2 == 1 ? values[m] : 0.5 * (values[m - 1] + values[m]);
    }

    private static long CpuNs()
    {
        if (ClockGetTime(ThreadCpuClock, out Timespec t) != 0)
        {
            throw new InvalidOperationException("clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
        }

        return (t.Seconds * 1_000_000_000L) + t.Nanoseconds;
    }

    [LibraryImport("libc", EntryPoint = "clock_gettime")]
    private static partial int ClockGetTime(int clockId, out Timespec time);

    [StructLayout(LayoutKind.Sequential)]
    private struct Timespec
    {
        public long Seconds;
        public long Nanoseconds;
    }
}
