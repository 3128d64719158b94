namespace URWPGSim2D.Collision.Benchmarks.Hosting;

/// <summary>
/// The cost of running a team's strategy in a sandboxed strategy host instead of the server's
/// process. Both cases ask team 0 (two fish, a small SDK strategy compiled from source) for one
/// cycle's decisions on the default match's snapshot 500 cycles in: <see cref="InProcess"/> (the
/// baseline) on its own thread in the server (<c>--isolation none</c>), <see cref="Hosted"/> in its
/// host process (snapshot out as a protocol line, packed as the server's hosts ask for it, decisions
/// back; the host decides on the thread that reads the line). The difference is the per-cycle cost of
/// isolation; <see cref="HostCyclePartsBenchmarks"/> times its parts besides the hand-overs. <see cref="HostStartToFirstDecision"/> starts a host for the already compiled
/// strategy, takes its first decision and stops it; <see cref="PooledHostToFirstDecision"/> does the same
/// with a host started ahead and waiting (<see cref="HostPool"/>), as matches get theirs. <see cref="Remote"/> plays the same strategy on a
/// remote client (<c>connect</c>'s code, on a thread of this process) over a loopback TCP
/// connection (<c>--strategy 0=remote:PORT</c>).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class IsolationBenchmarks
{
    private const string Source = """
        using System;
        using URWPGSim2D.Strategies;
        public sealed class Ahead : IStrategy
        {
            public string TeamName => "ahead";
            public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
            {
                for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, s.Fish[fish[i]].Heading > 0 ? 5 : 9);
            }
        }
        """;

    private Match _match = null!;
    private StrategyCaller _inProcess = null!;
    private StrategyCaller _hosted = null!;
    private StrategyCaller _remote = null!;
    private RemoteSeat _seat = null!;
    private System.Threading.Thread _client = null!;
    private PreparedStrategy _prepared = null!;
    private string _folder = null!;
    private int[] _fish0 = null!;
    private HostProcess _waiting = null!;

    /// <summary>Compiles the strategy, plays 500 cycles and starts both line-ups (the host's first call included).</summary>
    [GlobalSetup]
    public void Setup()
    {
        _folder = Directory.CreateTempSubdirectory("urwpg-bench-").FullName;
        string file = Path.Combine(_folder, "Ahead.cs");
        File.WriteAllText(file, Source);
        _prepared = StrategyResolver.Prepare(file)!;
        _match = MatchBuilder.Build(DefaultScenario.Load(), null, cycles: 10_000_000);
        for (int i = 0; i < 500; i++)
        {
            _match.Step();
        }

        _fish0 = [.. TeamFish(0)];
        _inProcess = new StrategyCaller([new StrategySlot("team 0", StrategyResolver.Load(file), 0, _fish0, isolated: true)], MatchBuilder.DefaultStrategyTimeoutMs);
        _hosted = new StrategyCaller([new StrategySlot("team 0", Start(), 0, _fish0)], MatchBuilder.DefaultStrategyTimeoutMs);
        _seat = new RemoteSeat(0, System.Net.IPAddress.Loopback, 0, "bench", TimeSpan.FromSeconds(30), _ => { });
        var remote = _seat.Open(Assignment());
        var strategy = StrategyResolver.Load(file);
        _client = new System.Threading.Thread(() =>
        {
            using var socket = new System.Net.Sockets.Socket(System.Net.Sockets.SocketType.Stream, System.Net.Sockets.ProtocolType.Tcp) { NoDelay = true };
            socket.Connect(_seat.EndPoint);
            using var stream = new System.Net.Sockets.NetworkStream(socket);
            new StrategyClient(stream, stream).Play(strategy, "bench");
        }) { IsBackground = true };
        _client.Start();
        remote.WaitForClient();
        _remote = new StrategyCaller([new StrategySlot("team 0", remote, 0, _fish0)], MatchBuilder.DefaultStrategyTimeoutMs);
        _inProcess.Decide(_match.Snapshot, _match.World.Fish);
        _hosted.Decide(_match.Snapshot, _match.World.Fish);
        _remote.Decide(_match.Snapshot, _match.World.Fish);
    }

    /// <summary>Stops the host and deletes the strategy's folder.</summary>
    [GlobalCleanup]
    public void Cleanup()
    {
        _inProcess.Stop();
        _hosted.Stop();
        _remote.Stop();
        _client.Join();
        _seat.Dispose();
        Directory.Delete(_folder, recursive: true);
    }

    /// <summary>Team 0's decisions for one cycle, strategy on its thread in the server's process.</summary>
    [Benchmark(Baseline = true)]
    public void InProcess() => _inProcess.Decide(_match.Snapshot, _match.World.Fish);

    /// <summary>Team 0's decisions for one cycle, strategy in its sandboxed host process.</summary>
    [Benchmark]
    public void Hosted() => _hosted.Decide(_match.Snapshot, _match.World.Fish);

    /// <summary>Team 0's decisions for one cycle, strategy on a remote client over loopback TCP.</summary>
    [Benchmark]
    public void Remote() => _remote.Decide(_match.Snapshot, _match.World.Fish);

    /// <summary>Starting a host for the compiled strategy up to its first decision, then stopping it.</summary>
    [Benchmark]
    public int HostStartToFirstDecision()
    {
        var caller = new StrategyCaller([new StrategySlot("team 0", Start(), 0, _fish0)], MatchBuilder.DefaultStrategyTimeoutMs);
        caller.Decide(_match.Snapshot, _match.World.Fish);
        int faults = caller.TotalFaults;
        caller.Stop();
        return faults == 0 ? 0 : throw new InvalidOperationException("the host faulted: " + caller.Slots[0].FirstFault);
    }

    /// <summary>Starts a waiting host for the next <see cref="PooledHostToFirstDecision"/> and gives it time to warm up (a match's host has the match's setup for that).</summary>
    [IterationSetup(Target = nameof(PooledHostToFirstDecision))]
    public void StartWaitingHost()
    {
        _waiting = HostProcess.StartWaiting(_prepared.ReadOnly, HostSandbox.Use(SandboxMode.Auto), HostSettings.Default);
        System.Threading.Thread.Sleep(2000);
    }

    /// <summary>Handing the compiled strategy to a waiting host up to its first decision, then stopping it.</summary>
    [Benchmark]
    public int PooledHostToFirstDecision()
    {
        var caller = new StrategyCaller([new StrategySlot("team 0", HostedStrategy.HandOver(_waiting, _prepared, Assignment(), 10_000), 0, _fish0)], MatchBuilder.DefaultStrategyTimeoutMs);
        caller.Decide(_match.Snapshot, _match.World.Fish);
        int faults = caller.TotalFaults;
        caller.Stop();
        return faults == 0 ? 0 : throw new InvalidOperationException("the host faulted: " + caller.Slots[0].FirstFault);
    }

    private StrategyConnection Start() => HostedStrategy.Start(_prepared, HostSettings.Default, Assignment(), 10_000, pooled: false);

    private URWPGSim2D.Protocol.AssignmentMessage Assignment() => new(
        1, 0, "", "match", _fish0, _match.World.Fish.Length, _match.World.Balls.Length, 0, MatchBuilder.DefaultStrategyTimeoutMs,
        _match.World.Field.Length, _match.World.Field.Width, _match.World.Obstacles);

    private System.Collections.Generic.IEnumerable<int> TeamFish(int team)
    {
        for (int i = 0; i < _match.World.Fish.Length; i++)
        {
            if (_match.World.Fish[i].Team == team)
            {
                yield return i;
            }
        }
    }
}
