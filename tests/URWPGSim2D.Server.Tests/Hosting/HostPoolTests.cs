using System;
using System.Diagnostics;
using System.IO;
using URWPGSim2D.Server.Cli;
using URWPGSim2D.Server.Hosting;
using URWPGSim2D.Server.Tests.Cli;
using Xunit;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Pre-started strategy hosts (<see cref="HostPool"/>): a team's compiled strategy goes to a host that
/// was started and warmed up before the match, in the same sandbox, with the match's CPU limit set
/// at the hand-over; a waiting host that never gets its strategy line ends.
/// </summary>
public sealed class HostPoolTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-pool-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void A_compiled_strategy_plays_in_a_waiting_host_with_the_matchs_cpu_limit()
    {
        // The strategy reports the command line of its host and its CPU time limit, and throws every cycle.
        string file = Path.Combine(_folder, "Limits.cs");
        File.WriteAllText(file, """
            using System; using System.IO; using System.Linq; using URWPGSim2D.Strategies;
            public sealed class Limits : IStrategy
            {
                public string TeamName => "Limits";
                public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
                {
                    string args = File.ReadAllText("/proc/self/cmdline").Replace('\0', ' ').Trim();
                    string cpu = File.ReadAllLines("/proc/self/limits").First(l => l.StartsWith("Max cpu time"));
                    throw new Exception("host=" + args.Substring(args.IndexOf(" host ")) + "; cpu=" + string.Join(" ", cpu.Split(' ', StringSplitOptions.RemoveEmptyEntries).Skip(3).Take(2)) + ";");
                }
            }
            """);

        // A scratch size of its own: the test's waiting host is no other test's.
        var run = CliRun.Of(string.Empty, "run", "--cycles", "3", "--strategy-timeout", "1000", "--strategy-scratch", "61", "--strategy", "0=" + file);
        Assert.True(run.ExitCode == 0, run.Stderr);
        int at = run.Stdout.IndexOf("first: cycle 1: Exception: ", StringComparison.Ordinal);
        Assert.True(at >= 0, run.Stdout);
        string report = run.Stdout[at..].Split('\n')[0];

        // 60 s for the start and twice the match's 3 cycles of 1 s.
        Assert.Contains("host= host -; cpu=66 66;", report, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("")]
    [InlineData("not a line\n")]
    public void A_waiting_host_without_a_strategy_line_ends_as_disconnected(string input)
    {
        var start = new ProcessStartInfo(HostProcess.DotnetProgram) { RedirectStandardInput = true, RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (string arg in new[] { HostProcess.ServerAssembly, "host", HostProcess.WaitingSpec })
        {
            start.ArgumentList.Add(arg);
        }

        using var host = Process.Start(start)!;
        host.StandardInput.Write(input);
        host.StandardInput.Close();
        string output = host.StandardOutput.ReadToEnd();
        host.WaitForExit();
        Assert.Equal(HostCommand.Disconnected, host.ExitCode);
        Assert.Equal(string.Empty, output);
    }
}
