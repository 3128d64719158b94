using System;
using System.IO;
using URWPGSim2D.Server.Tests.Cli;
using Xunit;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// In a strategy host the deadline counts the CPU time of every thread of the host, not only the
/// deciding thread's: a strategy cannot hide its work on threads of its own. The strategy below
/// measures CPU time itself, so the outcome does not depend on how busy the machine is.
/// </summary>
public sealed class HostTimeTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-time-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Theory]
    [InlineData("auto")]
    [InlineData("off")]
    public void Work_on_the_strategys_own_threads_counts_against_its_deadline(string sandbox)
    {
        // In cycle 2 two threads spin until the process has used 1.5 s more CPU time, while the
        // deciding thread only waits for them (it uses next to none itself); the deadline is 1 s.
        string file = Path.Combine(_folder, "Helpers.cs");
        File.WriteAllText(file, """
            using System; using System.Diagnostics; using System.Threading; using URWPGSim2D.Strategies;
            public sealed class Helpers : IStrategy
            {
                public string TeamName => "Helpers";
                public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
                {
                    for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);
                    if (s.Cycle != 1) return;
                    var me = Process.GetCurrentProcess();
                    TimeSpan until = me.TotalProcessorTime + TimeSpan.FromMilliseconds(1500);
                    var spinners = new Thread[2];
                    for (int t = 0; t < spinners.Length; t++)
                    {
                        spinners[t] = new Thread(() => { var p = Process.GetCurrentProcess(); while (true) { p.Refresh(); if (p.TotalProcessorTime >= until) break; } });
                        spinners[t].Start();
                    }

                    foreach (var t in spinners) t.Join();
                }
            }
            """);
        var run = CliRun.Of(string.Empty, "run", "--cycles", "4", "--strategy-timeout", "1000", "--sandbox", sandbox, "--strategy", "0=" + file);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("first: cycle 2: no decision within 1000 ms", run.Stdout, StringComparison.Ordinal);
    }
}
