using System.Net.Sockets;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Hostile and broken strategies written in the original's API (<c>URWPGSim2D.Strategy.Strategy</c>,
/// <c>GetDecision(Mission, int)</c>), as sources: each plays a whole match in a sandboxed strategy
/// host, the fault is charged to its team (summary, trace, results line), nothing outside the host's
/// scratch folder is written, no secret is read, no connection is made, and the server (this test
/// process) goes on. Probes report what they managed in an exception's message in cycle 1. No outcome
/// depends on a race with a clock: a strategy that hangs never answers, and the well-behaved cycles
/// have a deadline far beyond what they need.
/// </summary>
public sealed class HostileOriginalApiTests() : TempFolderTest("urwpg-hostile-orig-")
{
    private const string Deadline = "1000"; // ms of CPU time (and 10 s of wall time); the strategies' honest cycles need well under 1 ms

    private string Source(string name, string body, string members = "") => OriginalSource.Write(Folder, name, body, members);

    private static CliRun Run(string spec, int cycles = 12, params string[] more) =>
        CliRun.Of(string.Empty, ["run", "--cycles", cycles.ToString(System.Globalization.CultureInfo.InvariantCulture), "--strategy", "0=" + spec, "--strategy-timeout", Deadline, "--sandbox", "required", .. more]);

    // The fault line of team 0, after "team 0 (NAME.cs): ".
    private static string Faults(CliRun run)
    {
        Assert.True(run.ExitCode == 0, run.Stderr);
        int at = run.Stdout.IndexOf("  team 0 (", StringComparison.Ordinal);
        Assert.True(at >= 0, "no fault line for team 0:\n" + run.Stdout);
        string line = run.Stdout[at..].Split('\n')[0];
        return line[(line.IndexOf("): ", StringComparison.Ordinal) + 3)..];
    }

    [Attack("faults", "its host ends")]
    [Theory]
    [InlineData("Overflow", "if (cycle == 2) Recurse(0);", "static int Recurse(int n) { return Recurse(n + 1) + 1; }", 3, "killed by signal 6")]
    [InlineData("Exiter", "if (cycle == 4) Environment.Exit(7);", "", 5, "exit code 7")]
    [InlineData("Killer", "if (cycle == 1) System.Diagnostics.Process.GetCurrentProcess().Kill();", "", 2, "killed by signal 9")]
    public void A_strategy_that_ends_its_host_is_charged_once_and_the_match_is_played(string name, string body, string members, int cycle, string how)
    {
        string trace = Path.Combine(Folder, name + ".jsonl");
        var run = Run(Source(name, body, members), 12, "--trace", trace);
        Assert.StartsWith("match: 12 cycles,", run.Stdout, StringComparison.Ordinal);
        string faults = Faults(run);
        Assert.StartsWith($"0 exceptions, 0 timeouts, 0 bad answers, strategy host ended in cycle {cycle}; its fish kept their last decisions until then and stopped after; first: cycle {cycle}: strategy host ended: {how}", faults, StringComparison.Ordinal);

        // The trace has the fault in the line of its cycle, and only there; the fish stop after it.
        string[] lines = File.ReadAllLines(trace);
        Assert.Equal(13, lines.Length);
        for (int c = 0; c <= 12; c++)
        {
            Assert.Equal(c == cycle, lines[c].Contains("{\"kind\":\"fault\",\"team\":0,\"text\":\"team 0 (" + name + " [" + name + ".cs]) strategy ended, its fish stop: strategy host ended: " + how, StringComparison.Ordinal));
        }
    }

    [Attack("faults", "its host ends")]
    [Attack("faults", "with `--isolation none`: a constructor")]
    [Theory]
    [InlineData("BadCtor", "public Strategy() { throw new InvalidOperationException(\"no team today\"); }", "no team today")]
    [InlineData("BadStatic", "static readonly int Never = int.Parse(\"not a number\"); public Strategy() { cycle = Never; }", "(FormatException: ")]
    public void A_constructor_that_throws_is_charged_and_the_match_is_played_in_a_host_or_in_process(string name, string members, string why)
    {
        string source = Source(name, "", members);
        foreach (string isolation in new[] { "process", "none" })
        {
            string trace = Path.Combine(Folder, $"{name}-{isolation}.jsonl");
            string results = Path.Combine(Folder, $"{name}-{isolation}-results.jsonl");
            var run = Run(source, 12, "--isolation", isolation, "--trace", trace);
            Assert.StartsWith("match: 12 cycles,", run.Stdout, StringComparison.Ordinal);
            string faults = Faults(run);
            string first = isolation == "process"
                ? "first: cycle 1: strategy host ended: exit code 4: cannot create strategy URWPGSim2D.Strategy.Strategy from "
                : "first: cycle 1: cannot create strategy URWPGSim2D.Strategy.Strategy from ";
            Assert.StartsWith(isolation == "process"
                ? "0 exceptions, 0 timeouts, 0 bad answers, strategy host ended in cycle 1; its fish kept their last decisions until then and stopped after; " + first
                : "0 exceptions, 0 timeouts, 0 bad answers, strategy not created; its fish stopped for the whole match; " + first, faults, StringComparison.Ordinal);
            Assert.Contains(why, faults, StringComparison.Ordinal);
            string[] lines = File.ReadAllLines(trace);
            Assert.Contains("{\"kind\":\"fault\",\"team\":0,", lines[1], StringComparison.Ordinal);
            Assert.DoesNotContain(lines.Skip(2), l => l.Contains("\"fault\"", StringComparison.Ordinal));

            // A batch: every match is played and its line has the fault in its "faults" array.
            var batch = Run(source, 6, "--isolation", isolation, "--batch", "2", "--threads", "1", "--results", results);
            Assert.True(batch.ExitCode == 0, batch.Stderr);
            string[] matches = File.ReadAllLines(results).Skip(1).ToArray();
            Assert.Equal(2, matches.Length);
            Assert.All(matches, l => Assert.Contains("\"strategyFaults\":1,\"faults\":[{\"team\":0,\"strategy\":\"" + name + ".cs\",\"exceptions\":0,\"timeouts\":0,\"badAnswers\":0,\"crashes\":1,\"" + first.Replace("first: ", "first\":\"", StringComparison.Ordinal), l, StringComparison.Ordinal));
        }
    }

    [Attack("faults", "its host stops answering altogether")]
    [Fact]
    public void A_strategy_that_hangs_never_answers_spends_its_bank_and_plays_idle_after()
    {
        // It sleeps forever from cycle 3: no CPU is used, no answer ever comes, whatever the machine's
        // speed; the server waits as long as a call could take without spending the 1 s bank (2 × 2 s + 1 s), then kills its host.
        var run = Run(Source("Sleeper", "if (cycle == 2) System.Threading.Thread.Sleep(System.Threading.Timeout.Infinite);"), 8, "--time-bank", "1");
        Assert.StartsWith("match: 8 cycles,", run.Stdout, StringComparison.Ordinal);
        Assert.Equal("0 exceptions, 1 timeouts, 0 bad answers, out of time in cycle 3; its fish kept their last decisions until then and stopped after; first: cycle 3: time bank spent: no answer within 5.0 s; the team plays idle for the rest of the match", Faults(run));
    }

    [Attack("faults", "the strategy throws")]
    [Attack("sandbox", "memory")]
    [Fact]
    public void A_memory_hog_past_the_limit_is_charged_and_the_match_is_played()
    {
        var run = Run(Source("Hog", "if (cycle >= 2) while (true) Hoard.Add(new byte[1 << 20]);", "static readonly List<byte[]> Hoard = new List<byte[]>();"), 8, "--strategy-memory", "128");
        Assert.StartsWith("match: 8 cycles,", run.Stdout, StringComparison.Ordinal);
        string faults = Faults(run);
        // The heap limit is met in cycle 3: an OutOfMemoryException there (the host may then end too, but not before).
        Assert.Matches(@"^\d+ exceptions, 0 timeouts, 0 bad answers.*; first: cycle 3: (OutOfMemoryException|strategy host ended)", faults);
        Assert.DoesNotContain("first: cycle 1", faults, StringComparison.Ordinal);
    }

    [Attack("sandbox", "files")]
    [Fact]
    public void A_strategy_cannot_write_outside_its_scratch_folder()
    {
        string outside = Path.Combine(Folder, "written-by-strategy.txt");
        string home = Source("Writer", "", "");
        string own = File.ReadAllText(home);
        home = Source("Writer", $$"""
            if (cycle != 0) return d;
            string said = "";
            foreach (string path in new[] { @"{{outside}}", @"{{home}}", "/tmp/urwpg-orig-escape.txt", "/usr/urwpg-orig-escape.txt", "/home/urwpg-orig-escape.txt" })
            {
                try { File.WriteAllText(path, "x"); said += "wrote " + path + ";"; }
                catch (Exception e) { said += e.GetType().Name + ";"; }
            }
            File.WriteAllText("log.txt", "fine");
            throw new Exception(said + " scratch " + File.ReadAllText("log.txt"));
            """);
        string faults = Faults(Run(home));
        Assert.DoesNotContain("wrote " + home, faults, StringComparison.Ordinal);
        Assert.DoesNotContain("wrote /usr", faults, StringComparison.Ordinal);
        Assert.DoesNotContain("wrote /home", faults, StringComparison.Ordinal);
        Assert.EndsWith("scratch fine", faults, StringComparison.Ordinal);
        Assert.False(File.Exists(outside));
        Assert.False(File.Exists("/tmp/urwpg-orig-escape.txt"));
        Assert.False(File.Exists("log.txt")); // not in the server's working directory either
        Assert.NotEqual(own, File.ReadAllText(home)); // the source is the hostile one, unchanged by it
        Assert.Contains("scratch \" + File.ReadAllText", File.ReadAllText(home), StringComparison.Ordinal);
    }

    [Attack("sandbox", "files")]
    [Attack("sandbox", "environment")]
    [Fact]
    public void A_strategy_cannot_read_a_secret_or_the_servers_environment()
    {
        string secret = Path.Combine(Folder, "secret.txt");
        File.WriteAllText(secret, "TOPSECRET");
        Environment.SetEnvironmentVariable("URWPG_ORIG_TEST_TOKEN", "TOPSECRET");
        string faults = Faults(Run(Source("Reader", $$"""
            if (cycle != 0) return d;
            string said = "";
            foreach (string path in new[] { @"{{secret}}", "/etc/passwd", "/etc/shadow", "/proc/1/environ" })
            {
                try { said += File.ReadAllText(path); } catch (Exception e) { said += e.GetType().Name + ";"; }
            }
            said += Environment.GetEnvironmentVariable("URWPG_ORIG_TEST_TOKEN") ?? "no token;";
            throw new Exception(said);
            """)));
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
        using var datagrams = new UdpClient(new IPEndPoint(IPAddress.Loopback, 0));
        try
        {
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            int udp = ((IPEndPoint)datagrams.Client.LocalEndPoint!).Port;
            string faults = Faults(Run(Source("Caller", $$"""
                if (cycle != 0) return d;
                string said = "";
                try { using (var c = new System.Net.Sockets.TcpClient()) { c.Connect("127.0.0.1", {{port}}); said += "connected;"; } }
                catch (Exception e) { said += e.GetType().Name + ";"; }
                try { using (var c = new System.Net.Sockets.TcpClient()) { c.Connect("1.1.1.1", 53); said += "reached the internet;"; } }
                catch (Exception e) { said += e.GetType().Name + ";"; }
                try { using (var u = new System.Net.Sockets.UdpClient()) { u.Send(new byte[] { 1 }, 1, "127.0.0.1", {{udp}}); } }
                catch (Exception e) { said += e.GetType().Name + ";"; }
                throw new Exception(said);
                """)));
            Assert.DoesNotContain("connected", faults, StringComparison.Ordinal);
            Assert.DoesNotContain("reached", faults, StringComparison.Ordinal);
            Assert.False(listener.Pending(), "a connection reached the test's listener");
            Assert.Equal(0, datagrams.Available); // the datagram went to the sandbox's own loopback, if anywhere
        }
        finally
        {
            listener.Stop();
        }
    }

    [Attack("sandbox", "processes")]
    [Fact]
    public void A_strategy_cannot_find_or_kill_the_server()
    {
        int server = Environment.ProcessId;
        string faults = Faults(Run(Source("Hunter", $$"""
            if (cycle != 0) return d;
            string said = "";
            foreach (var p in System.Diagnostics.Process.GetProcesses()) { if (p.Id == {{server}} || p.ProcessName == "dotnet" && p.Id != Environment.ProcessId) said += "sees " + p.Id + ";"; }
            try { System.Diagnostics.Process.GetProcessById({{server}}).Kill(); said += "killed the server;"; }
            catch (Exception e) { said += e.GetType().Name + ";"; }
            said += kill({{server}}, 9) == 0 ? "signalled the server;" : "no signal;";
            said += kill(-1, 9) == 0 ? "signalled everything;" : "no broadcast;";
            throw new Exception(said);
            """, "[DllImport(\"libc\")] static extern int kill(int pid, int sig);")));
        Assert.DoesNotContain("sees ", faults, StringComparison.Ordinal);
        Assert.DoesNotContain("killed the server", faults, StringComparison.Ordinal);
        Assert.DoesNotContain("signalled the server", faults, StringComparison.Ordinal);
        Assert.Contains("no signal;", faults, StringComparison.Ordinal);
    }

    [Attack("faults", "its host ends")]
    [Fact]
    public void A_batch_with_a_crashing_original_strategy_keeps_every_result_line()
    {
        string results = Path.Combine(Folder, "results.jsonl");
        var run = Run(Source("Overflow", "if (cycle == 2) Recurse(0);", "static int Recurse(int n) { return Recurse(n + 1) + 1; }"), 8, "--batch", "3", "--threads", "2", "--results", results);
        Assert.True(run.ExitCode == 0, run.Stderr);
        string[] lines = File.ReadAllLines(results);
        Assert.Equal(4, lines.Length);
        Assert.All(lines.Skip(1), l => Assert.Contains("\"crashes\":1,\"first\":\"cycle 3: strategy host ended: killed by signal 6", l, StringComparison.Ordinal));
    }
}
