using System.Net.Sockets;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Hostile and broken strategies (written for these tests) each play a whole match in a sandboxed
/// strategy host: the fault is charged to the team, the match and the server go on. Strategies that
/// probe the sandbox report what they managed in the message of an exception they throw in cycle 1,
/// so the test reads the outcome from the fault report. No outcome depends on a race with a clock:
/// a strategy that hangs, hangs forever.
/// </summary>
public sealed class HostileStrategyTests() : TempFolderTest("urwpg-hostile-")
{
    private const string Header = "using System; using System.IO; using System.Collections.Generic; using System.Runtime.InteropServices; using URWPGSim2D.Strategies;\n";

    // An SDK strategy whose Decide body is given (s: snapshot, d: decisions).
    private string Sdk(string name, string body, string members = "") =>
        SdkStrategy.Write(Folder, name, name, "for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);\n" + body, members, Header);

    // A deadline no honest call comes near on a loaded machine (ms of CPU time, 10 s of wall time), unless a test needs a short one.
    private static CliRun Run(string spec, int cycles = 20, params string[] more) => RunWithin("1000", spec, cycles, more);

    private static CliRun RunWithin(string deadline, string spec, int cycles, params string[] more) =>
        CliRun.Of(string.Empty, ["run", "--cycles", cycles.ToString(System.Globalization.CultureInfo.InvariantCulture), "--strategy", "0=" + spec, "--strategy-timeout", deadline, "--sandbox", "required", .. more]);

    // The fault line of team 0, after "team 0 (NAME.cs): ".
    private static string Faults(CliRun run)
    {
        Assert.True(run.ExitCode == 0, run.Stderr);
        int at = run.Stdout.IndexOf("  team 0 (", StringComparison.Ordinal);
        Assert.True(at >= 0, "no fault line for team 0:\n" + run.Stdout);
        string line = run.Stdout[at..].Split('\n')[0];
        return line[(line.IndexOf("): ", StringComparison.Ordinal) + 3)..];
    }

    [Attack("faults", "the strategy throws")]
    [Fact]
    public void A_strategy_that_throws_every_cycle_is_charged_every_cycle()
    {
        var run = Run(Sdk("Thrower", "throw new InvalidOperationException(\"boom\");"));
        Assert.StartsWith("match: 20 cycles,", run.Stdout, StringComparison.Ordinal);
        Assert.Equal("20 exceptions, 0 timeouts, 0 bad answers; its fish kept their last decisions; first: cycle 1: InvalidOperationException: boom", Faults(run));
    }

    [Attack("faults", "its host ends")]
    [Theory]
    [InlineData("Overflow", "if (s.Cycle == 2) Recurse(0);", "static int Recurse(int n) => Recurse(n + 1) + 1;", 3, "")]
    [InlineData("Exiter", "if (s.Cycle == 4) Environment.Exit(7);", "", 5, "exit code 7")]
    [InlineData("FailFaster", "if (s.Cycle == 0) Environment.FailFast(\"gone\");", "", 1, "")]
    [InlineData("Segfault", "if (s.Cycle == 1) Marshal.WriteInt64(new IntPtr(0x7f0000000008), 1);", "", 2, "")]
    [InlineData("Suicide", "if (s.Cycle == 1) System.Diagnostics.Process.GetCurrentProcess().Kill();", "", 2, "killed by signal 9")]
    public void A_strategy_that_ends_its_host_stops_its_fish_and_the_match_goes_on(string name, string body, string members, int cycle, string how)
    {
        var run = Run(Sdk(name, body, members));
        Assert.StartsWith("match: 20 cycles,", run.Stdout, StringComparison.Ordinal);
        string faults = Faults(run);
        Assert.StartsWith($"0 exceptions, 0 timeouts, 0 bad answers, strategy host ended in cycle {cycle}; its fish kept their last decisions until then and stopped after; first: cycle {cycle}: strategy host ended: ", faults, StringComparison.Ordinal);
        Assert.Contains(how, faults, StringComparison.Ordinal);
    }

    [Attack("faults", "its host stops answering altogether")]
    [Fact]
    public void A_host_that_stops_answering_is_killed_when_its_bank_is_spent()
    {
        // The strategy stops its whole process (SIGSTOP): the host can no longer answer at all. The
        // server waits as long as the call could take without spending the 1 s bank (2 × 1.05 s + 1 s), then kills the host.
        var run = RunWithin("50", Sdk("Freezer", "if (s.Cycle == 1) kill(getpid(), 19);",
            "[DllImport(\"libc\")] static extern int kill(int pid, int sig); [DllImport(\"libc\")] static extern int getpid();"), 5, "--time-bank", "1");
        Assert.Equal("0 exceptions, 1 timeouts, 0 bad answers, out of time in cycle 2; its fish kept their last decisions until then and stopped after; first: cycle 2: time bank spent: no answer within 3.1 s; the team plays idle for the rest of the match", Faults(run));
        Assert.Contains("\n  team 0 (Freezer [Freezer.cs]): 1 late call, 1.000 s drawn, bank spent, slowest call ", run.Stdout, StringComparison.Ordinal);
    }

    [Attack("faults", "its time bank is spent")]
    [Fact]
    public void A_strategy_that_spins_forever_spends_its_bank_and_the_match_goes_on_without_it()
    {
        var run = Run(Sdk("Spinner", "if (s.Cycle >= 3) while (true) { }"), 20, "--time-bank", "1");
        Assert.StartsWith("match: 20 cycles,", run.Stdout, StringComparison.Ordinal);
        Assert.Equal("0 exceptions, 1 timeouts, 0 bad answers, out of time in cycle 4; its fish kept their last decisions until then and stopped after; first: cycle 4: time bank spent: no answer within 5.0 s; the team plays idle for the rest of the match", Faults(run));
    }

    [Attack("faults", "the strategy throws")]
    [Attack("sandbox", "memory")]
    [Fact]
    public void A_memory_bomb_hits_the_heap_limit_and_is_charged()
    {
        var run = Run(Sdk("Bomb", "while (true) Hoard.Add(new byte[1 << 20]);", "static readonly List<byte[]> Hoard = new();"), 5, "--strategy-memory", "128");
        string faults = Faults(run);
        Assert.True(faults.Contains("OutOfMemoryException", StringComparison.Ordinal) || faults.Contains("strategy host ended", StringComparison.Ordinal), faults);
    }

    [Attack("faults", "its host ends")]
    [Theory]
    [InlineData("BadCtor", "public BadCtor() { throw new InvalidOperationException(\"no team today\"); }")]
    [InlineData("BadStatic", "static readonly int Never = int.Parse(\"not a number\"); public BadStatic() { _ = Never; }")]
    public void A_constructor_that_throws_is_charged_and_the_match_is_played(string name, string members)
    {
        var run = Run(Sdk(name, "", members));
        Assert.StartsWith("match: 20 cycles,", run.Stdout, StringComparison.Ordinal);
        string faults = Faults(run);
        Assert.StartsWith("0 exceptions, 0 timeouts, 0 bad answers, strategy host ended in cycle 1;", faults, StringComparison.Ordinal);
        Assert.Contains("exit code 4: cannot create strategy " + name, faults, StringComparison.Ordinal);
    }

    [Attack("sandbox", "files")]
    [Fact]
    public void A_strategy_cannot_write_outside_its_scratch_folder()
    {
        string outside = Path.Combine(Folder, "written-by-strategy.txt");
        string home = Path.Combine(Folder, "Writer.cs");
        var run = Run(Sdk("Writer", $$"""
            if (s.Cycle != 0) return;
            string said = "";
            foreach (string path in new[] { @"{{outside}}", @"{{home}}", "/tmp/urwpg-escape.txt", "/usr/urwpg-escape.txt" })
            {
                try { File.WriteAllText(path, "x"); said += "wrote " + path + ";"; }
                catch (Exception e) { said += e.GetType().Name + ";"; }
            }
            File.WriteAllText("scratch.txt", "fine");
            throw new Exception(said + " scratch " + File.ReadAllText("scratch.txt"));
            """));
        // Writes into the sandbox's private /tmp succeed but vanish with it; nothing reaches the real files.
        string faults = Faults(run);
        Assert.DoesNotContain("wrote " + home, faults, StringComparison.Ordinal);
        Assert.DoesNotContain("wrote /usr", faults, StringComparison.Ordinal);
        Assert.EndsWith("scratch fine", faults, StringComparison.Ordinal);
        Assert.False(File.Exists(outside));
        Assert.False(File.Exists("/tmp/urwpg-escape.txt"));
        Assert.StartsWith(Header, File.ReadAllText(home), StringComparison.Ordinal);
    }

    [Attack("sandbox", "files")]
    [Attack("sandbox", "environment")]
    [Fact]
    public void A_strategy_cannot_read_a_secret_or_another_teams_files_or_the_environment()
    {
        string secret = Path.Combine(Folder, "secret.txt");
        File.WriteAllText(secret, "TOPSECRET");
        Environment.SetEnvironmentVariable("URWPG_TEST_TOKEN", "TOPSECRET");
        var run = Run(Sdk("Reader", $$"""
            if (s.Cycle != 0) return;
            string said = "";
            foreach (string path in new[] { @"{{secret}}", "/etc/passwd", "/root/.bashrc" })
            {
                try { said += File.ReadAllText(path); } catch (Exception e) { said += e.GetType().Name + ";"; }
            }
            said += Environment.GetEnvironmentVariable("URWPG_TEST_TOKEN") ?? "no token;";
            said += Directory.Exists(@"{{Folder}}") ? " sees the test folder" : " no test folder";
            throw new Exception(said);
            """));
        string faults = Faults(run);
        Assert.DoesNotContain("TOPSECRET", faults, StringComparison.Ordinal);
        Assert.DoesNotContain("root:", faults, StringComparison.Ordinal);
        Assert.Contains("no token;", faults, StringComparison.Ordinal);
    }

    [Attack("sandbox", "network")]
    [Fact]
    public void A_strategy_cannot_open_a_connection()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            var run = Run(Sdk("Caller", $$"""
                if (s.Cycle != 0) return;
                string said = "";
                try { using var c = new System.Net.Sockets.TcpClient(); c.Connect("127.0.0.1", {{port}}); said += "connected;"; }
                catch (Exception e) { said += e.GetType().Name + ";"; }
                try { System.Net.Dns.GetHostAddresses("example.com"); said += "resolved;"; }
                catch (Exception e) { said += e.GetType().Name + ";"; }
                throw new Exception(said);
                """));
            string faults = Faults(run);
            Assert.DoesNotContain("connected", faults, StringComparison.Ordinal);
            Assert.DoesNotContain("resolved", faults, StringComparison.Ordinal);
            Assert.False(listener.Pending(), "a connection reached the test's listener");
        }
        finally
        {
            listener.Stop();
        }
    }

    [Attack("sandbox", "processes")]
    [Fact]
    public void A_strategy_cannot_see_or_signal_the_server()
    {
        int server = Environment.ProcessId;
        var run = Run(Sdk("Hunter", $$"""
            if (s.Cycle != 0) return;
            string said = "";
            foreach (var p in System.Diagnostics.Process.GetProcesses()) if (p.Id == {{server}}) said += "sees the server;";
            try { System.Diagnostics.Process.GetProcessById({{server}}).Kill(); said += "killed the server;"; }
            catch (Exception e) { said += e.GetType().Name + ";"; }
            said += kill({{server}}, 0) == 0 ? "can signal the server;" : "no signal;";
            throw new Exception(said);
            """, "[DllImport(\"libc\")] static extern int kill(int pid, int sig);"));
        string faults = Faults(run);
        Assert.DoesNotContain("sees the server", faults, StringComparison.Ordinal);
        Assert.DoesNotContain("killed the server", faults, StringComparison.Ordinal);
        Assert.Contains("no signal;", faults, StringComparison.Ordinal);
    }

    [Attack("sandbox", "user")]
    [Attack("sandbox", "core dumps")]
    [Fact]
    public void A_strategy_runs_as_nobody_without_capabilities_or_core_dumps()
    {
        // The strategy reads its own user, capabilities and core-file limit from /proc and says them.
        var run = Run(Sdk("Whoami", """
            if (s.Cycle != 0) return;
            string said = "";
            foreach (string line in File.ReadAllLines("/proc/self/status"))
                if (line.StartsWith("Uid:") || line.StartsWith("CapEff:") || line.StartsWith("CapBnd:")) said += line.Replace('\t', ' ') + ";";
            foreach (string line in File.ReadAllLines("/proc/self/limits"))
                if (line.StartsWith("Max core file size")) said += string.Join(" ", line.Split(' ', StringSplitOptions.RemoveEmptyEntries)) + ";";
            throw new Exception(said);
            """));
        string faults = Faults(run);
        Assert.Contains("Uid: 65534 65534 65534 65534;", faults, StringComparison.Ordinal); // nobody, in its own user namespace
        Assert.Contains("CapEff: 0000000000000000;", faults, StringComparison.Ordinal);
        Assert.Contains("Max core file size 0 0 bytes;", faults, StringComparison.Ordinal);
    }

    [Attack("faults", "its host ends")]
    [Fact]
    public void A_batch_with_a_crashing_strategy_keeps_every_result_line()
    {
        string results = Path.Combine(Folder, "results.jsonl");
        var run = Run(Sdk("Overflow", "if (s.Cycle == 2) Recurse(0);", "static int Recurse(int n) => Recurse(n + 1) + 1;"), 10, "--batch", "3", "--threads", "1", "--results", results);
        Assert.True(run.ExitCode == 0, run.Stderr);
        string[] lines = File.ReadAllLines(results);
        Assert.Equal(4, lines.Length); // header + 3 matches
        for (int i = 1; i < 4; i++)
        {
            Assert.Contains("\"crashes\":1,\"first\":\"cycle 3: strategy host ended: ", lines[i], StringComparison.Ordinal);
        }
    }
}
