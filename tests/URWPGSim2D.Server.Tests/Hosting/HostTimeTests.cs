namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// In a strategy host the time of a call counts the CPU time of every thread and every process of the
/// host's sandbox, not only the deciding thread's: a strategy cannot hide its work on threads or
/// processes of its own. The strategies below measure CPU time themselves, so the outcome does not
/// depend on how busy the machine is; the time banks are too small for what they use.
/// </summary>
public sealed class HostTimeTests() : TempFolderTest("urwpg-time-")
{
    [Attack("sandbox", "CPU")]
    [Theory]
    [InlineData("auto")]
    [InlineData("off")]
    public void Work_on_the_strategys_own_threads_counts_against_its_time(string sandbox)
    {
        Assert.True(SandboxCgroup.Unavailable is null, "CI runs where control groups can be made: " + SandboxCgroup.Unavailable);
        // In cycle 2 two threads spin until the process has used 2.5 s more CPU time, while the
        // deciding thread only waits for them (it uses next to none itself); the deadline is 1 s.
        string file = SdkStrategy.Write(Folder, "Helpers", "Helpers", """
            for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);
            if (s.Cycle != 1) return;
            var me = Process.GetCurrentProcess();
            TimeSpan until = me.TotalProcessorTime + TimeSpan.FromMilliseconds(2500);
            var spinners = new Thread[2];
            for (int t = 0; t < spinners.Length; t++)
            {
                spinners[t] = new Thread(() => { var p = Process.GetCurrentProcess(); while (true) { p.Refresh(); if (p.TotalProcessorTime >= until) break; } });
                spinners[t].Start();
            }

            foreach (var t in spinners) t.Join();
            """, usings: "using System; using System.Diagnostics; using System.Threading; using URWPGSim2D.Strategies;");
        // 2.5 s of CPU time in a call allowed 1 s, and 5 s of wall time (the spinners take about 1.3 s on
        // two free cores): on a free machine only the CPU time of the helper threads spends the 1 s bank.
        var run = CliRun.Of(string.Empty, "run", "--cycles", "4", "--strategy-timeout", "1000", "--time-bank", "1", "--sandbox", sandbox, "--strategy", "0=" + file);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("team 0 (Helpers", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("out of time in cycle 2", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("first: cycle 2: time bank spent: ", run.Stdout, StringComparison.Ordinal);
    }

    // An SDK strategy whose Decide body is given (s: snapshot, d: decisions).
    private string Sdk(string name, string body, string members = "") =>
        SdkStrategy.Write(Folder, name, name, "for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);\n" + body, members,
            "using System; using System.Diagnostics; using System.IO; using System.Threading; using URWPGSim2D.Strategies;");

    [Attack("faults", "its time bank is spent")]
    [Fact]
    public void A_strategy_that_sleeps_through_every_call_spends_its_bank_and_plays_idle()
    {
        // 950 ms of sleep a call, allowed 200 ms of wall time: at least 750 ms from the 2 s bank each
        // call after the first (whose allowance is 2 s), so the bank is spent by cycle 4 on any machine.
        var run = CliRun.Of(string.Empty, "run", "--cycles", "30", "--strategy-timeout", "100", "--time-bank", "2", "--sandbox", "required", "--strategy", "0=" + Sdk("Sleeper", "Thread.Sleep(950);"));
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.StartsWith("match: 30 cycles,", run.Stdout, StringComparison.Ordinal);
        Assert.Matches(@"team 0 \(Sleeper \[Sleeper\.cs\]\): 0 exceptions, 1 timeouts, 0 bad answers, out of time in cycle [234]; its fish kept their last decisions until then and stopped after; first: cycle [234]: time bank spent: ", run.Stdout);
        Assert.Matches(@"\n  team 0 \(Sleeper \[Sleeper\.cs\]\): [123] late calls?, 2\.000 s drawn, bank spent, slowest call \d+ ms\n", run.Stdout);
    }

    [Attack("sandbox", "CPU")]
    [Fact]
    public void Work_in_child_processes_counts_against_the_strategys_time()
    {
        Assert.True(SandboxCgroup.Unavailable is null, "CI runs where control groups can be made: " + SandboxCgroup.Unavailable);

        // In cycle 2 the strategy starts two shells that spin, waits (sleeping) until they have used
        // 2.5 s of CPU time together, and ends them: about 1.3 s of wall time on two free cores, within
        // the 5 s a call of 2.5 s of CPU time may take; only their CPU time spends the 1 s bank.
        string file = Sdk("Forker", """
            if (s.Cycle != 1) return;
            var children = new Process[2];
            for (int k = 0; k < children.Length; k++)
            {
                var start = new ProcessStartInfo("/bin/sh") { UseShellExecute = false };
                start.ArgumentList.Add("-c");
                start.ArgumentList.Add("while :; do :; done");
                children[k] = Process.Start(start)!;
            }

            while (true)
            {
                Thread.Sleep(20);
                double used = 0;
                foreach (var c in children) { c.Refresh(); used += c.TotalProcessorTime.TotalSeconds; }
                if (used >= 2.5) break;
            }

            foreach (var c in children) c.Kill();
            """);
        var run = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy-timeout", "1000", "--time-bank", "1", "--sandbox", "required", "--strategy", "0=" + file);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("team 0 (Forker [Forker.cs]): 0 exceptions, 1 timeouts, 0 bad answers, out of time in cycle 2;", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("first: cycle 2: time bank spent: ", run.Stdout, StringComparison.Ordinal);
    }

    [Attack("faults", "a call uses more than its deadline")]
    [Fact]
    public void The_same_tournament_twice_with_a_strategy_slow_every_twentieth_call_gives_the_same_results()
    {
        // Every twentieth call computes for 300 ms of CPU time against a 100 ms deadline. The match
        // waits for it and takes 200 ms from the team's bank (5 s for 200 cycles): the answers that
        // count, and so every result, are the same however fast or busy the machine is.
        string slow = Sdk("Slow", """
            if (s.Cycle % 20 != 19) { Chase(s, fish, d); return; }
            var me = Process.GetCurrentProcess();
            TimeSpan until = me.TotalProcessorTime + TimeSpan.FromMilliseconds(300);
            while (true) { me.Refresh(); if (me.TotalProcessorTime >= until) break; }
            Chase(s, fish, d);
            """, """
            private static void Chase(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
            {
                for (int i = 0; i < d.Length; i++)
                {
                    var f = s.Fish[fish[i]];
                    float dx = s.Balls[0].Position.X - f.Position.X, dz = s.Balls[0].Position.Y - f.Position.Y;
                    float turn = MathF.Atan2(dz, dx) - f.Heading;
                    while (turn > MathF.PI) turn -= 2 * MathF.PI;
                    while (turn < -MathF.PI) turn += 2 * MathF.PI;
                    d[i] = new Decision(12, Math.Clamp((int)MathF.Round(7 + (turn * 4)), 0, 14));
                }
            }
            """);
        string[] Results(string name)
        {
            string output = Path.Combine(Folder, name);
            var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "slow=" + slow, "--entrant", "chaser=chase-ball", "--seeds", "2", "--cycles", "200", "--out", output);
            Assert.True(run.ExitCode == 0, run.Stderr);
            return File.ReadAllLines(Path.Combine(output, "results.jsonl"));
        }

        string[] first = Results("first"), second = Results("second");
        Assert.Equal(first, second);
        Assert.DoesNotContain("\"faults\"", string.Join("\n", first), StringComparison.Ordinal);
    }
}
