namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Hostile strategies against the limits of the sandbox as a whole: processes they start (daemons
/// in a new session, a fork bomb) end with their host, whatever they do; native memory counts against
/// the sandbox's memory and is charged as the host running out of memory; scratch and /tmp are small
/// RAM-backed file systems. Whether anything is left running is checked by the kernel's own
/// identities: the PID namespace a strategy reports (no process of the machine may still be in it)
/// and, without bubblewrap, the processes' IDs and their control group. These tests need bubblewrap
/// and cgroups (the test machine has both; .ci/install-bubblewrap).
/// </summary>
public sealed class SandboxLimitTests() : TempFolderTest("urwpg-limits-")
{
    private const string Header = "using System; using System.IO; using System.Linq; using System.Collections.Generic; using System.Diagnostics; using System.Runtime.InteropServices; using URWPGSim2D.Strategies;\n";

    private string Sdk(string name, string body, string members = "") =>
        SdkStrategy.Write(Folder, name, name, "for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);\n" + body, members, Header);

    private static CliRun Run(string spec, int cycles, params string[] more) =>
        CliRun.Of(string.Empty, ["run", "--cycles", cycles.ToString(CultureInfo.InvariantCulture), "--strategy", "0=" + spec, .. more, .. Array.IndexOf(more, "--strategy-timeout") < 0 ? new[] { "--strategy-timeout", "1000" } : []]);

    private static string Faults(CliRun run)
    {
        Assert.True(run.ExitCode == 0, run.Stderr);
        int at = run.Stdout.IndexOf("  team 0 (", StringComparison.Ordinal);
        Assert.True(at >= 0, "no fault line for team 0:\n" + run.Stdout);
        string line = run.Stdout[at..].Split('\n')[0];
        return line[(line.IndexOf("): ", StringComparison.Ordinal) + 3)..];
    }

    // The text between "<key>=" and the next ';' in a strategy's report.
    private static string Field(string report, string key)
    {
        int at = report.IndexOf(key + "=", StringComparison.Ordinal);
        Assert.True(at >= 0, $"no {key} in: {report}");
        int start = at + key.Length + 1;
        int end = report.IndexOf(';', start);
        return report[start..end];
    }

    // Whether the process PID exists and has not ended. An ended process whose parent has gone
    // stays a zombie until the machine's init reaps it (a container's first process may never do).
    private static bool Running(int pid)
    {
        try
        {
            string stat = File.ReadAllText("/proc/" + pid.ToString(CultureInfo.InvariantCulture) + "/stat");
            return stat[(stat.LastIndexOf(')') + 2)..][0] != 'Z';
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    // The running processes of the machine in the PID namespace "pid:[N]", by their IDs.
    private static List<int> InNamespace(string ns)
    {
        var found = new List<int>();
        foreach (string dir in Directory.EnumerateDirectories("/proc"))
        {
            if (int.TryParse(Path.GetFileName(dir), NumberStyles.None, CultureInfo.InvariantCulture, out int pid))
            {
                try
                {
                    if (new FileInfo(Path.Combine(dir, "ns", "pid")).LinkTarget == ns && Running(pid))
                    {
                        found.Add(pid);
                    }
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    // ended meanwhile
                }
            }
        }

        return found;
    }

    // Starts NAME ARGS in a new session (setsid), its output to nowhere, and returns at once.
    private const string Daemon = """
        static void Daemon(string args)
        {
            var p = new ProcessStartInfo("/usr/bin/setsid") { UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true, RedirectStandardInput = true };
            p.ArgumentList.Add("/bin/sh"); p.ArgumentList.Add("-c"); p.ArgumentList.Add(args);
            Process.Start(p);
        }
        """;

    [Attack("sandbox", "processes")]
    [Fact]
    public void Daemons_a_strategy_starts_in_new_sessions_end_with_its_sandbox()
    {
        Assert.Null(Sandbox.Unavailable);

        // A spinner and a sleeper in new sessions, each double-forked away from the host, then the
        // strategy reports its PID namespace and how many processes it sees, and throws every cycle.
        var run = Run(Sdk("Daemons", """
            if (s.Cycle == 0)
            {
                Daemon("(while :; do :; done) & (exec sleep 1000) & exit 0");
                Daemon("(exec sleep 2000 > held.txt) & exit 0");
                System.Threading.Thread.Sleep(300);
            }
            int seen = Directory.GetDirectories("/proc").Count(p => int.TryParse(Path.GetFileName(p), out _));
            throw new Exception("ns=" + new FileInfo("/proc/self/ns/pid").LinkTarget + "; seen=" + seen + ";");
            """, Daemon), 3, "--sandbox", "required");
        string faults = Faults(run);
        Assert.StartsWith("3 exceptions,", faults, StringComparison.Ordinal);
        string ns = Field(faults, "ns");
        Assert.StartsWith("pid:[", ns, StringComparison.Ordinal);
        Assert.True(int.Parse(Field(faults, "seen"), CultureInfo.InvariantCulture) >= 5, faults); // the daemons ran
        Assert.Empty(InNamespace(ns));
    }

    // Says its PID namespace, then starts processes that fork without end (until the process limit)
    // while their sandbox is torn down: double-forked sleepers, a fork-and-exec loop and a spinner,
    // each in a new session; says "forking" when they have had a moment (its own work, no fork).
    private const string Forkers = """
        readlink /proc/self/ns/pid
        setsid sh -c 'while :; do (sleep 1000 &); done' >/dev/null 2>&1 &
        setsid sh -c 'while :; do /bin/true; done' >/dev/null 2>&1 &
        setsid sh -c 'while :; do :; done' >/dev/null 2>&1 &
        i=0; while [ $i -lt 20000 ]; do i=$((i + 1)); done
        echo forking

        """;

    [Attack("sandbox", "processes")]
    [Theory]
    [InlineData(true)] // the first process ends by itself, as a host does at the end of its match: its bubblewrap ends the namespace
    [InlineData(false)] // the server ends the sandbox while its first process runs
    public void A_sandbox_forking_while_it_is_torn_down_has_nothing_running_when_teardown_returns(bool endsByItself)
    {
        Assert.Null(Sandbox.Unavailable);
        Assert.Null(SandboxCgroup.Unavailable);
        for (int i = 0; i < 12; i++)
        {
            var group = SandboxCgroup.Create(256L << 20, 300, out string? problem);
            Assert.True(group is not null, problem);
            var start = new System.Diagnostics.ProcessStartInfo("/bin/sh") { UseShellExecute = false, RedirectStandardOutput = true };
            foreach (string arg in group.Wrapper().Skip(1))
            {
                start.ArgumentList.Add(arg);
            }

            start.ArgumentList.Add(Sandbox.Bwrap);
            foreach (string arg in Sandbox.Arguments([], Path.Combine(Folder, "scratch"), new Dictionary<string, string> { ["PATH"] = "/usr/bin:/bin" }, 1 << 20))
            {
                start.ArgumentList.Add(arg);
            }

            start.ArgumentList.Add("/bin/sh");
            start.ArgumentList.Add("-c");
            start.ArgumentList.Add(Forkers + (endsByItself ? "exit 0" : "exec sleep 1000"));
            using var process = System.Diagnostics.Process.Start(start)!;
            try
            {
                string ns = process.StandardOutput.ReadLine() ?? "";
                Assert.StartsWith("pid:[", ns, StringComparison.Ordinal);
                Assert.Equal("forking", process.StandardOutput.ReadLine());
                group.Remember(); // as the server does at a host's first answer
                if (endsByItself)
                {
                    process.WaitForExit(); // the outer bubblewrap has gone: the kernel now ends the namespace on its own
                }
                else
                {
                    Assert.InRange(group.Tasks(), 5, 300); // the sandbox is busy forking
                }

                Assert.True(group.KillAll());
                Assert.Equal(0, group.Tasks() - group.Zombies()); // every task of the sandbox reaped, or a zombie of it: none runs
                Assert.Empty(InNamespace(ns));
                group.Dispose();
            }
            finally
            {
                group.Dispose();
                process.WaitForExit();
            }
        }
    }

    [Attack("faults", "it starts more processes or threads")]
    [Attack("sandbox", "processes")]
    [Fact]
    public void A_fork_bomb_meets_the_process_limit_and_leaves_nothing_behind()
    {
        Assert.Null(SandboxCgroup.Unavailable);
        var run = Run(Sdk("ForkBomb", """
            if (s.Cycle != 0) return;
            int started = 0; string stop = "none";
            try
            {
                for (int i = 0; i < 1500; i++)
                {
                    var p = new ProcessStartInfo("/bin/sleep", "1000") { UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true, RedirectStandardInput = true };
                    Process.Start(p);
                    started++;
                }
            }
            catch (Exception e) { stop = e.GetType().Name; }
            throw new Exception("ns=" + new FileInfo("/proc/self/ns/pid").LinkTarget + "; started=" + started + "; stop=" + stop + ";");
            """), 2, "--sandbox", "required", "--strategy-processes", "100");
        string faults = Faults(run);
        int started = int.Parse(Field(faults, "started"), CultureInfo.InvariantCulture);
        Assert.InRange(started, 1, 99); // its own threads count too
        Assert.NotEqual("none", Field(faults, "stop"));
        Assert.Empty(InNamespace(Field(faults, "ns")));
    }

    [Attack("platforms", "Linux without bubblewrap, with control groups")]
    [Fact]
    public void Without_bubblewrap_its_control_group_still_ends_every_daemon()
    {
        Assert.Null(SandboxCgroup.Unavailable);

        // No PID namespace here: the daemons write their real process IDs, and the strategy its control group.
        var run = Run(Sdk("PlainDaemons", """
            if (s.Cycle == 0)
            {
                Daemon("(echo $$ > a.pid; while :; do :; done) & exit 0");
                Daemon("(echo $$ > b.pid; exec sleep 1000) & exit 0");
                while (!File.Exists("a.pid") || !File.Exists("b.pid") || new FileInfo("a.pid").Length == 0 || new FileInfo("b.pid").Length == 0) System.Threading.Thread.Sleep(10);
            }
            string group = File.ReadAllLines("/proc/self/cgroup").First(l => l.Split(':')[1].Split(',').Contains("pids") || l.StartsWith("0::", StringComparison.Ordinal)).Split(':', 3)[2];
            throw new Exception("a=" + File.ReadAllText("a.pid").Trim() + "; b=" + File.ReadAllText("b.pid").Trim() + "; group=" + group + ";");
            """, Daemon), 2, "--sandbox", "off");
        string faults = Faults(run);
        foreach (string key in new[] { "a", "b" })
        {
            int pid = int.Parse(Field(faults, key), CultureInfo.InvariantCulture);
            Assert.False(Running(pid), $"process {pid} is still running: {faults}");
        }

        string group = Field(faults, "group");
        Assert.Contains("urwpgsim2d-", group, StringComparison.Ordinal);
        foreach (string mount in new[] { "/sys/fs/cgroup/pids", "/sys/fs/cgroup" })
        {
            Assert.False(Directory.Exists(mount + group) && mount + group != mount + "/", $"control group {mount + group} is left");
        }
    }

    [Attack("sandbox", "processes")]
    [Fact]
    public void A_group_left_by_a_killed_server_is_ended_and_removed_by_the_next_one()
    {
        Assert.Null(SandboxCgroup.Unavailable);
        var layout = SandboxCgroup.Machine!;

        // A process that has ended stands for the killed server; its group still holds a daemon.
        using var gone = Process.Start(new ProcessStartInfo("/bin/true") { UseShellExecute = false })!;
        gone.WaitForExit();
        string name = $"urwpgsim2d-{gone.Id}-1";
        var group = SandboxCgroup.Create(layout, name, 64L << 20, 16, out string? problem);
        Assert.True(group is not null, problem);
        var start = new ProcessStartInfo("/bin/sh") { UseShellExecute = false, RedirectStandardOutput = true };
        foreach (string argument in group.Wrapper().Skip(1).Concat(["/bin/sh", "-c", "echo $$; exec sleep 1000"]))
        {
            start.ArgumentList.Add(argument);
        }

        using var daemon = Process.Start(start)!;
        int pid = int.Parse(daemon.StandardOutput.ReadLine()!, CultureInfo.InvariantCulture);
        Assert.Equal([pid], group.Processes());

        Assert.True(SandboxCgroup.SweepStale(layout, Running) >= 1);

        daemon.WaitForExit();
        Assert.False(Running(pid), $"the daemon {pid} of the stale group still runs");
        foreach (string parent in layout.Parents)
        {
            Assert.False(Directory.Exists(Path.Combine(parent, name)), $"the stale group {Path.Combine(parent, name)} is left");
        }
    }

    [Attack("sandbox", "memory")]
    [Attack("faults", "its host ends")]
    [Fact]
    public void Native_memory_counts_against_the_sandbox_and_is_charged_as_out_of_memory()
    {
        Assert.Null(SandboxCgroup.Unavailable);

        // 4 GiB outside the GC heap, every page written; the sandbox has 64 + 256 + 2 × 16 MiB. (A
        // deadline of a minute: the kernel may take seconds to give up reclaiming memory.)
        var run = Run(Sdk("NativeHog", """
            if (s.Cycle != 1) return;
            var page = new byte[1 << 20];
            for (int i = 0; i < 4096; i++) { IntPtr p = Marshal.AllocHGlobal(1 << 20); Marshal.Copy(page, 0, p, page.Length); }
            throw new Exception("allocated 4 GiB");
            """), 5, "--sandbox", "required", "--strategy-memory", "64", "--strategy-scratch", "16", "--strategy-timeout", "60000");
        string faults = Faults(run);
        Assert.StartsWith("0 exceptions, 0 timeouts, 0 bad answers, strategy host ended in cycle 2;", faults, StringComparison.Ordinal);
        Assert.Contains("strategy host ended: out of memory: its sandbox reached its limit of 352 MiB, killed", faults, StringComparison.Ordinal);
    }

    [Attack("sandbox", "disk")]
    [Attack("faults", "it starts more processes or threads")]
    [Fact]
    public void Scratch_tmp_and_shared_memory_are_small_ram_file_systems_a_strategy_fills_alone()
    {
        Assert.Null(Sandbox.Unavailable);

        // Writes up to 1 GiB into each; reports how much fit, where, and what stopped it.
        var run = Run(Sdk("DiskFiller", """
            if (s.Cycle != 0) return;
            string said = "";
            var block = new byte[1 << 20];
            foreach (string path in new[] { "fill.bin", "/tmp/fill.bin", "/dev/shm/fill.bin" })
            {
                long written = 0;
                try { using var f = File.Create(path); for (int i = 0; i < 1024; i++) { f.Write(block); f.Flush(); written += block.Length; } }
                catch (IOException) { }
                said += path + "=" + (written >> 20) + ";";
                File.Delete(path);
            }
            var drive = new DriveInfo(Directory.GetCurrentDirectory());
            throw new Exception(said + " format=" + drive.DriveFormat + "; size=" + (drive.TotalSize >> 20) + ";");
            """), 2, "--sandbox", "required", "--strategy-scratch", "8");
        string faults = Faults(run);
        Assert.Equal("tmpfs", Field(faults, "format"));
        Assert.Equal("8", Field(faults, "size"));
        foreach (string path in new[] { "fill.bin", "/tmp/fill.bin", "/dev/shm/fill.bin" })
        {
            Assert.InRange(int.Parse(Field(faults, path), CultureInfo.InvariantCulture), 1, 8);
        }
    }

    [Theory]
    [InlineData("--strategy-scratch", "0", "run: --strategy-scratch must be an integer 1..65536, got \"0\"")]
    [InlineData("--strategy-processes", "31", "run: --strategy-processes must be an integer 32..65536, got \"31\"")]
    [InlineData("--strategy-processes", "many", "run: --strategy-processes must be an integer 32..65536, got \"many\"")]
    public void A_bad_limit_is_refused_with_one_line(string option, string value, string message)
    {
        var run = CliRun.Of(string.Empty, "run", "--cycles", "1", option, value);
        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith(message + ". Usage: ", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
    }
}
