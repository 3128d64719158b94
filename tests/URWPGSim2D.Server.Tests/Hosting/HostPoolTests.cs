namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Pre-started strategy hosts (<see cref="HostPool"/>): a team's compiled strategy goes to a host that
/// was started and warmed up before the match, in the same sandbox, with the match's CPU limit set
/// at the hand-over; a waiting host that never gets its strategy line ends.
/// </summary>
public sealed class HostPoolTests() : TempFolderTest("urwpg-pool-")
{
    [Fact]
    public void A_compiled_strategy_plays_in_a_waiting_host_with_the_matchs_cpu_limit()
    {
        // The strategy reports the command line of its host and its CPU time limit, and throws every cycle.
        string file = SdkStrategy.Write(Folder, "Limits", "Limits", """
            string args = File.ReadAllText("/proc/self/cmdline").Replace('\0', ' ').Trim();
            string cpu = File.ReadAllLines("/proc/self/limits").First(l => l.StartsWith("Max cpu time"));
            throw new Exception("host=" + args.Substring(args.IndexOf(" host ")) + "; cpu=" + string.Join(" ", cpu.Split(' ', StringSplitOptions.RemoveEmptyEntries).Skip(3).Take(2)) + ";");
            """, usings: "using System; using System.IO; using System.Linq; using URWPGSim2D.Strategies;");

        // A scratch size of its own: the test's waiting host is no other test's.
        var run = CliRun.Of(string.Empty, "run", "--cycles", "3", "--strategy-timeout", "1000", "--strategy-scratch", "61", "--strategy", "0=" + file);
        Assert.True(run.ExitCode == 0, run.Stderr);
        int at = run.Stdout.IndexOf("first: cycle 1: Exception: ", StringComparison.Ordinal);
        Assert.True(at >= 0, run.Stdout);
        string report = run.Stdout[at..].Split('\n')[0];

        // 60 s for the start and twice the match's 3 cycles of 1 s; the hard limit a second later (SIGXCPU first).
        Assert.Contains("host= host -; cpu=66 67;", report, StringComparison.Ordinal);
    }

    [Fact]
    public void A_tournaments_hosted_entrant_plays_every_match_in_a_waiting_host()
    {
        // The strategy throws every cycle with the command line of its host: "host -" for a pre-started one, "host PATH" for one started for it.
        string file = SdkStrategy.Write(Folder, "Which", "Which", """
            string args = File.ReadAllText("/proc/self/cmdline").Replace('\0', ' ').Trim();
            throw new Exception("host=" + args.Substring(args.IndexOf(" host ") + 6) + ";");
            """, usings: "using System; using System.IO; using URWPGSim2D.Strategies;");

        // Two seeds against the demo, ends swapped: four matches, one after the other; a scratch size of its own, as above.
        string output = Path.Combine(Folder, "t");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "which=" + file,
            "--seeds", "2", "--cycles", "3", "--strategy-timeout", "5000", "--strategy-scratch", "62", "--threads", "1", "--out", output);
        Assert.True(run.ExitCode == 0, run.Stderr);
        string[] matches = File.ReadAllLines(Path.Combine(output, "results.jsonl"))[1..];
        Assert.Equal(4, matches.Length);
        foreach (string line in matches)
        {
            Assert.Contains("cycle 1: Exception: host=-;", line, StringComparison.Ordinal);
        }
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
