using System;
using System.Diagnostics;
using System.Globalization;
using System.Runtime;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Hosting;

namespace URWPGSim2D.CrowdCpu;

/// <summary>
/// One whole cycle of the crowd scene (<c>run --crowd N</c>: <see cref="CrowdScenario"/> through
/// <see cref="MatchBuilder"/>, the uniform grid, one thread) timed by the thread's CPU clock (the
/// clock of strategies' deadlines, <see cref="ThreadTimeClock"/>), so that other work on the machine
/// hardly moves it:
/// <c>URWPGSim2D.CrowdCpu N[,N...] WARM MEASURE</c> plays WARM cycles of each scene, then times
/// MEASURE cycles one by one, and prints <c>crowd N CPU_MS WALL_MS</c> per scene (the medians, ms).
/// </summary>
internal static class Program
{
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

            var clock = new ThreadTimeClock();
            var cpu = new double[measure];
            var wall = new double[measure];
            for (int i = 0; i < measure; i++)
            {
                clock.CallStarting();
                match.Step();
                (TimeSpan c, TimeSpan w) = clock.CallEnded();
                cpu[i] = c.TotalMilliseconds;
                wall[i] = w.TotalMilliseconds;
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

    // A throwaway 1,000-body match played until the JIT has compiled nothing new for a second (at
    // least 2 s, at most 30 s), so that the timed cycles run the final tier-1 code even when the
    // machine is loaded and the background compilations are slow.
    private static void WarmUp()
    {
        Match match = Build(1000);
        var clock = Stopwatch.StartNew();
        long compiled = JitInfo.GetCompiledMethodCount();
        TimeSpan still = TimeSpan.Zero;
        while (clock.Elapsed < TimeSpan.FromSeconds(30) && (clock.Elapsed < TimeSpan.FromSeconds(2) || clock.Elapsed - still < TimeSpan.FromSeconds(1)))
        {
            match.Step();
            if (JitInfo.GetCompiledMethodCount() != compiled)
            {
                compiled = JitInfo.GetCompiledMethodCount();
                still = clock.Elapsed;
            }
        }
    }

    private static double Median(double[] values)
    {
        Array.Sort(values);
        int m = values.Length / 2;
        return values.Length % 2 == 1 ? values[m] : 0.5 * (values[m - 1] + values[m]);
    }
}
