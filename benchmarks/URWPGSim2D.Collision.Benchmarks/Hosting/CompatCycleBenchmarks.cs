using URWPGSim2D.Compat.Adapter;
using URWPGSim2D.Engine.BuiltInStrategies;

namespace URWPGSim2D.Collision.Benchmarks.Hosting;

/// <summary>
/// The cost of the original strategy API in a 2 × 2 match (the default match, 500 cycles in).
/// <see cref="Cycle"/> (the baseline) is one whole cycle with both teams on SDK strategies. The
/// Decide cases run only the strategies of one cycle on that match's current snapshot: both
/// teams on SDK strategies, team 0 on a strategy written against the original API
/// (<see cref="OriginalChaser"/>, behind the adapter that builds its deep copy of the mission every
/// call) against an SDK team, and both teams on the original API. <see cref="MissionCopy"/> is one
/// team's deep copy alone. A match with compat strategies costs Cycle − DecideAllSdk + its Decide
/// case per cycle. Strategies run inline (no strategy thread), so the differences are the
/// adapter's work: copy, call, answer.
/// </summary>
[MemoryDiagnoser]
public class CompatCycleBenchmarks
{
    private Match _match = null!;
    private StrategyCaller _sdk = null!;
    private StrategyCaller _mixed = null!;
    private StrategyCaller _compat = null!;
    private MissionBuilder _builder = null!;

    /// <summary>Builds the match, plays its first 500 cycles and sets up the three strategy line-ups.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var teams = new TeamStrategy?[] { new("team 0", new ChaseBallStrategy(), Isolated: false), new("team 1", new ChaseBallStrategy(), Isolated: false) };
        _match = MatchBuilder.Build(DefaultScenario.Load(), teams, cycles: 10_000_000);
        for (int i = 0; i < 500; i++)
        {
            _match.Step();
        }

        _sdk = Host(new ChaseBallStrategy(), new ChaseBallStrategy());
        _mixed = Host(new OriginalStrategyAdapter(new OriginalChaser()), new ChaseBallStrategy());
        _compat = Host(new OriginalStrategyAdapter(new OriginalChaser()), new OriginalStrategyAdapter(new OriginalChaser()));
        _builder = new MissionBuilder();
    }

    /// <summary>One whole cycle of the match, both teams on SDK strategies.</summary>
    [Benchmark(Baseline = true)]
    public void Cycle() => _match.Step();

    /// <summary>The strategies of one cycle, both teams on SDK strategies.</summary>
    [Benchmark]
    public void DecideAllSdk() => _sdk.Decide(_match.Snapshot, _match.World.Fish);

    /// <summary>The strategies of one cycle, team 0 on the original API, team 1 on the SDK.</summary>
    [Benchmark]
    public void DecideCompatVersusSdk() => _mixed.Decide(_match.Snapshot, _match.World.Fish);

    /// <summary>The strategies of one cycle, both teams on the original API.</summary>
    [Benchmark]
    public void DecideAllCompat() => _compat.Decide(_match.Snapshot, _match.World.Fish);

    /// <summary>One team's deep copy of the mission from the current snapshot (what the adapter builds each call).</summary>
    [Benchmark]
    public object MissionCopy() => _builder.Build(_match.Snapshot);

    private StrategyCaller Host(IStrategy team0, IStrategy team1)
    {
        int[] fish0 = [.. TeamFish(0)], fish1 = [.. TeamFish(1)];
        return new StrategyCaller(
            [new StrategySlot("team 0", team0, 0, fish0, isolated: false), new StrategySlot("team 1", team1, 1, fish1, isolated: false)],
            MatchBuilder.DefaultStrategyTimeoutMs);
    }

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
