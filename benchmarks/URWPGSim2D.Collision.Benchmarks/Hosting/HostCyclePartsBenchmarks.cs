using URWPGSim2D.Protocol;

namespace URWPGSim2D.Collision.Benchmarks.Hosting;

/// <summary>The parts of a hosted cycle besides the hand-overs: the cycle message written and read, the decisions written and read, the sandbox's CPU and waiting time read.</summary>
[MemoryDiagnoser]
[MedianColumn]
public class HostCyclePartsBenchmarks
{
    private Match _match = null!;
    private MessageWriter _writer = null!;
    private CycleReader _reader = null!;
    private byte[] _cycle = null!;
    private byte[] _packedCycle = null!;
    private byte[] _decisions = null!;
    private readonly Decision[] _answer = new Decision[2];
    private SandboxCgroup? _group;

    /// <summary>Plays 500 cycles of the default match.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _match = MatchBuilder.Build(DefaultScenario.Load(), null, cycles: 10_000_000);
        for (int i = 0; i < 500; i++)
        {
            _match.Step();
        }

        var a = new AssignmentMessage(1, 0, "", "match", [0, 1], _match.World.Fish.Length, _match.World.Balls.Length, 0, 100, _match.World.Field.Length, _match.World.Field.Width, _match.World.Obstacles);
        _writer = new MessageWriter();
        _reader = new CycleReader(a);
        _cycle = _writer.Cycle(_match.Snapshot).ToArray();
        _packedCycle = _writer.Cycle(_match.Snapshot, packed: true).ToArray();
        _decisions = _writer.Decisions(_match.Snapshot.Cycle, [new Decision(10, 5), new Decision(10, 9)]).ToArray();
        _group = HostCgroup.Create(HostSettings.Default);
        Console.WriteLine($"cycle line {_cycle.Length} bytes, packed {_packedCycle.Length}, cgroup {(_group is null ? "none" : "yes")}");
    }

    /// <summary>Removes the group.</summary>
    [GlobalCleanup]
    public void Cleanup() => _group?.Dispose();

    /// <summary>Server: the cycle message.</summary>
    [Benchmark]
    public int WriteCycle() => _writer.Cycle(_match.Snapshot).Length;

    /// <summary>Host: reading the cycle message.</summary>
    [Benchmark]
    public int ReadCycle() => _reader.Read(_cycle);

    /// <summary>Server: the packed cycle message.</summary>
    [Benchmark]
    public int WritePackedCycle() => _writer.Cycle(_match.Snapshot, packed: true).Length;

    /// <summary>Host: reading the packed cycle message.</summary>
    [Benchmark]
    public int ReadPackedCycle() => _reader.Read(_packedCycle);

    /// <summary>Host: the decisions message.</summary>
    [Benchmark]
    public int WriteDecisions() => _writer.Decisions(7, _answer).Length;

    /// <summary>Server: reading the decisions.</summary>
    [Benchmark]
    public int ReadDecisions() => (int)MessageReader.ReadDecisions(_decisions, _match.Snapshot.Cycle, _answer, out _);

    /// <summary>Server: the sandbox's CPU time and waiting time.</summary>
    [Benchmark]
    public TimeSpan? CgroupReads() => _group?.CpuTime() + _group?.WaitingTime();
}
