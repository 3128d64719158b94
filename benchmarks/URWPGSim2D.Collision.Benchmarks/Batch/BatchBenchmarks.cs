using URWPGSim2D.Tournament.Batch;

namespace URWPGSim2D.Collision.Benchmarks.Batch;

/// <summary>
/// A batch of 8 default matches of 300 cycles (seeds 1 to 8) played on 1 and on 2 threads: the
/// ratio of the two is the batch speed-up on two cores. Each call plays the whole batch.
/// </summary>
[MemoryDiagnoser]
public class BatchBenchmarks
{
    private const int Matches = 8;
    private const int Cycles = 300;
    private ScenarioDefinition _scene = null!;

    /// <summary>Matches played at once.</summary>
    [Params(1, 2)]
    public int Threads { get; set; }

    /// <summary>Parses the default match once.</summary>
    [GlobalSetup]
    public void Setup() => _scene = DefaultScenario.Load();

    /// <summary>Plays the batch; returns the goals scored (so nothing is optimised away).</summary>
    [Benchmark]
    public int Batch()
    {
        var header = new BatchHeader("default", string.Empty, "chase-ball;chase-ball", "scenario", 100, 1, Matches, Cycles, 0, 1);
        var results = BatchRunner.Run(header, Threads, seed => MatchBuilder.Build(_scene, seed: seed), _ => { });
        int goals = 0;
        foreach (var r in results)
        {
            goals += r.Goals0 + r.Goals1;
        }

        return goals;
    }
}
