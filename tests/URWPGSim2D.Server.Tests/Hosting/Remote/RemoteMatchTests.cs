using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Hosting.Remote;

/// <summary>
/// Whole matches with a remote team: the server (<c>run --strategy 0=remote:0</c>) and the client
/// (<c>connect</c>) each on a thread of the test, over loopback TCP. With answers in time the match
/// is the same, cycle by cycle, as the same strategy played in the server's process with the same
/// seed; tokens are checked; a server without a client gives up after <c>--remote-wait</c>.
/// The client plays original-API strategies in this test process, so these tests run alone
/// (<see cref="InProcessStaticsCollection"/>).
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class RemoteMatchTests() : TempFolderTest("urwpg-remote-")
{
    public static IEnumerable<object[]> Items()
    {
        foreach (var item in ItemRegistry.All)
        {
            yield return [item.Slug];
        }
    }

    [Theory]
    [MemberData(nameof(Items))]
    public void A_remote_team_plays_the_same_match_as_in_process(string item)
    {
        string sdk = SteadyStrategy.Write(Folder);
        foreach (string spec in new[] { sdk, OriginalStrategyTests.Folder("Dribbler") })
        {
            string local = Path.Combine(Folder, "local.jsonl"), remote = Path.Combine(Folder, "remote.jsonl");
            string[] match = ["run", "--item", item, "--seed", "3", "--cycles", "150", "--strategy-timeout", "20000", "--force", "--trace"];
            var a = CliRun.Of(string.Empty, [.. match, local, "--strategy", "0=" + spec, "--isolation", "none"]);
            var (b, client) = Remote([.. match, remote, "--strategy", "0=remote:0"], port => ["connect", $"127.0.0.1:{port}", spec]);
            Assert.True(a.ExitCode == 0 && b.ExitCode == 0 && client.ExitCode == 0, a.Stderr + b.Stderr + client.Stderr);
            Assert.Contains("strategy faults: none", b.Stdout, StringComparison.Ordinal);
            Assert.Matches(@"^match ended after \d+ cycles: -?\d+(:-?\d+)+, 0 fault\(s\) charged to this team\n$", client.Stdout);
            string[] x = File.ReadAllLines(local), y = File.ReadAllLines(remote);
            Assert.Equal(x.Length, y.Length);
            Assert.Equal(WithoutNames(x[0]), WithoutNames(y[0]));
            for (int i = 1; i < x.Length; i++)
            {
                Assert.True(x[i] == y[i], $"{item} {Path.GetFileName(spec)}: the traces differ at line {i + 1}");
            }
        }
    }

    [Fact]
    public void A_remote_slot_takes_only_a_client_with_its_token()
    {
        string[] run = ["run", "--item", "polo-1v1", "--cycles", "20", "--strategy", "1=remote:0", "--remote-token", "1=s3cret", "--strategy-timeout", "20000"];
        var stderr = new WatchedWriter();
        var server = Background(run, stderr);
        int port = stderr.WaitForPort();
        var intruder = CliRun.Of(string.Empty, "connect", $"127.0.0.1:{port}", "chase-ball", "--token", "guess");
        var owner = CliRun.Of(string.Empty, "connect", $"127.0.0.1:{port}", "chase-ball", "--token", "s3cret");
        var result = server();
        Assert.Equal(ConnectCommand.Refused, intruder.ExitCode);
        Assert.Equal("connect: the server refused the client: wrong token\n", intruder.Stderr);
        Assert.Equal(0, owner.ExitCode);
        Assert.Equal(0, result.ExitCode);
        Assert.Matches(@"team 1 \(remote\): 127\.0\.0\.1:\d+: refused a client: wrong token\n", stderr.ToString());
        Assert.Contains("team 1 (remote): client \"chase-ball\" connected from 127.0.0.1:", stderr.ToString(), StringComparison.Ordinal);
    }

    [Fact]
    public void Two_remote_teams_on_port_0_both_say_their_port_before_a_client_connects_and_are_named_by_their_clients()
    {
        string[] run = ["run", "--item", "polo-1v1", "--cycles", "20", "--strategy", "0=remote:0", "--strategy", "1=remote:0", "--strategy-timeout", "20000"];
        var stderr = new WatchedWriter();
        var server = Background(run, stderr);
        int[] ports = stderr.WaitForPorts(2); // no client has connected yet: the server waits for team 0's
        Assert.NotEqual(ports[0], ports[1]);
        Assert.DoesNotContain("connected from", stderr.ToString(), StringComparison.Ordinal);
        CliRun? second = null;
        var other = new Thread(() => second = CliRun.Of(string.Empty, "connect", $"127.0.0.1:{ports[1]}", "idle")) { IsBackground = true };
        other.Start();
        var first = CliRun.Of(string.Empty, "connect", $"127.0.0.1:{ports[0]}", "chase-ball");
        other.Join();
        var result = server();
        Assert.True(result.ExitCode == 0 && first.ExitCode == 0 && second!.ExitCode == 0, result.Stderr + first.Stderr + second!.Stderr);

        // Named by the names the clients sent, with the seat beside them.
        Assert.True(Regex.IsMatch("\n" + result.Stdout, @"\nscore: team 0 \(chase-ball \[remote:\d+\]\) \d+, team 1 \(idle \[remote:\d+\]\) \d+\n"), result.Stdout);
    }

    [Fact]
    public void A_server_without_a_client_gives_up_after_the_wait_with_one_line_and_exit_2()
    {
        string trace = Path.Combine(Folder, "never.jsonl");
        var stderr = new WatchedWriter();
        var result = Server(["run", "--cycles", "20", "--strategy", "0=remote:0", "--remote-wait", "1", "--trace", trace], stderr);
        Assert.Equal(2, result.ExitCode);
        Assert.Equal("", result.Stdout);
        Assert.Matches(@"^team 0 \(remote\): waiting for a client on 127\.0\.0\.1:(\d+)\n--strategy 0=remote: no client connected to 127\.0\.0\.1:\1 within 1 s \(--remote-wait\)\n$", stderr.ToString());
        Assert.False(File.Exists(trace));
    }

    [Fact]
    public void A_port_in_use_is_one_line_and_exit_2_before_the_match()
    {
        var taken = new System.Net.Sockets.TcpListener(System.Net.IPAddress.Loopback, 0);
        taken.Start();
        try
        {
            int port = ((System.Net.IPEndPoint)taken.LocalEndpoint).Port;
            var result = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy", $"1=remote:{port}");
            Assert.Equal(2, result.ExitCode);
            Assert.StartsWith($"--strategy 1: cannot listen on 127.0.0.1:{port}: ", result.Stderr, StringComparison.Ordinal);
            Assert.Single(result.Stderr.TrimEnd('\n').Split('\n'));
        }
        finally
        {
            taken.Stop();
        }
    }

    [Theory]
    [InlineData("run --strategy 0=remote:x", "run: --strategy TEAM=remote:PORT must be an integer 0..65535, got \"x\"")]
    [InlineData("run --strategy 0=remote:70000", "run: --strategy TEAM=remote:PORT must be an integer 0..65535, got \"70000\"")]
    [InlineData("run --remote-wait 5", "run: --remote-wait, --remote-host and --remote-token belong to --strategy TEAM=remote:PORT")]
    [InlineData("run --strategy 0=remote:0 --remote-wait 0", "run: --remote-wait must be an integer 1..86400, got \"0\"")]
    [InlineData("run --strategy 0=remote:0 --remote-host example.org", "run: --remote-host must be an IP address (127.0.0.1, 0.0.0.0, ::1, ...), got \"example.org\"")]
    [InlineData("run --strategy 0=remote:0 --remote-token 1=abc", "run: --remote-token for team 1, which is not remote")]
    [InlineData("run --strategy 0=remote:0 --remote-token a --remote-token b", "run: --remote-token given twice for team 0")]
    [InlineData("run --strategy 0=remote:0 --batch 2", "run: a remote team plays one match at a time: --batch and --slurm do not go with --strategy TEAM=remote:PORT")]
    [InlineData("run --strategy 0=remote:7000 --strategy 1=remote:7000", "run: both remote teams ask for port 7000; give each its own (or 0 for any free one)")]
    [InlineData("tournament --item polo-1v1 --out t --entrant a=remote:x --entrant b=idle", "tournament: --entrant NAME=remote:PORT must be an integer 0..65535, got \"x\"")]
    [InlineData("tournament --item polo-1v1 --out t --entrant a=idle --entrant b=chase-ball --remote-wait 5", "tournament: --remote-wait, --remote-host and --remote-token belong to --entrant NAME=remote:PORT")]
    [InlineData("tournament --item polo-1v1 --out t --entrant a=remote:7000 --entrant b=remote:7000", "tournament: remote entrants a and b both ask for port 7000; give each its own (or 0 for any free one)")]
    [InlineData("tournament --item polo-1v1 --out t --entrant a=remote:0 --entrant b=idle --remote-token b=x", "tournament: --remote-token for entrant b, which is not remote")]
    [InlineData("tournament --item polo-1v1 --out t --entrant a=remote:0 --entrant b=idle --remote-token x --remote-token y", "tournament: --remote-token given twice for every remote entrant")]
    [InlineData("tournament --item polo-1v1 --out t --entrant a=remote:0 --entrant b=idle --check", "tournament: a remote entrant plays its matches here, one at a time, with its client: --check, --slurm, --shard and --merge do not go with --entrant NAME=remote:PORT")]
    public void Bad_remote_options_are_one_line_and_exit_2(string arguments, string message)
    {
        var result = CliRun.Of(string.Empty, arguments.Split(' '));
        Assert.Equal(2, result.ExitCode);
        Assert.StartsWith(message + ". Usage: ", result.Stderr, StringComparison.Ordinal);
        Assert.Single(result.Stderr.TrimEnd('\n').Split('\n'));
    }

    [Theory]
    [InlineData("connect chase-ball", "connect: connect needs HOST:PORT and SPEC")]
    [InlineData("connect 127.0.0.1 chase-ball", "connect: HOST:PORT must be a host and a port 1..65535 (127.0.0.1:7000, [::1]:7000), got \"127.0.0.1\"")]
    [InlineData("connect 127.0.0.1:0 chase-ball", "connect: HOST:PORT must be a host and a port 1..65535 (127.0.0.1:7000, [::1]:7000), got \"127.0.0.1:0\"")]
    [InlineData("connect 127.0.0.1:7000 chase-ball --wait x", "connect: --wait must be an integer 0..86400 (seconds), once, got \"x\"")]
    [InlineData("connect 127.0.0.1:7000 chase-ball --colour red", "connect: unknown option \"--colour\"")]
    [InlineData("connect 127.0.0.1:7000 a b", "connect: unexpected argument \"b\"")]
    public void Bad_connect_arguments_are_one_line_and_exit_2(string arguments, string message)
    {
        var result = CliRun.Of(string.Empty, arguments.Split(' '));
        Assert.Equal(2, result.ExitCode);
        Assert.StartsWith(message + ". Usage: ", result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public void Connect_reports_a_strategy_it_cannot_load_with_exit_3()
    {
        var result = CliRun.Of(string.Empty, "connect", "127.0.0.1:7000", Path.Combine(Folder, "missing.dll"));
        Assert.Equal(3, result.ExitCode);
        Assert.DoesNotContain("   at ", result.Stderr, StringComparison.Ordinal);
    }

    // Runs the server on a thread and the client (given the port) on this one.
    internal static (CliRun Server, CliRun Client) Remote(string[] run, Func<int, string[]> client)
    {
        var stderr = new WatchedWriter();
        var server = Background(run, stderr);
        int port = stderr.WaitForPort();
        var c = CliRun.Of(string.Empty, client(port));
        return (server(), c);
    }

    // The server on its own thread; the function returned waits for its end.
    internal static Func<CliRun> Background(string[] run, WatchedWriter stderr)
    {
        CliRun? result = null;
        var thread = new Thread(() => result = Server(run, stderr)) { IsBackground = true };
        thread.Start();
        return () =>
        {
            thread.Join();
            return result!;
        };
    }

    private static CliRun Server(string[] run, WatchedWriter stderr)
    {
        using var output = new StringWriter();
        int code = CliApp.Run(run, new StringReader(string.Empty), output, stderr);
        return new CliRun(code, output.ToString(), stderr.ToString());
    }

    private static string WithoutNames(string header) => Regex.Replace(header, "\"name\":\"[^\"]*\"", "\"name\":\"\"");
}
