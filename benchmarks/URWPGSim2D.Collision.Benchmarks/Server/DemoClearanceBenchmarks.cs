using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Items.Demo;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Collision.Benchmarks.Server;

/// <summary>
/// What a demo strategy pays for one clearance on the main job's field (ball-grab: the borders and
/// six goal-box bars): the grid lookup it plans with (<see cref="ObstacleField.Clearance"/>, every
/// grid point already measured) against the library's exact signed distance the grid is filled from
/// (<see cref="ObstacleField.Measure"/>), over 1,024 fixed random points (seed 28), per point.
/// </summary>
[MemoryDiagnoser]
public class DemoClearanceBenchmarks
{
    private const int Points = 1024;
    private readonly Vector2[] _points = new Vector2[Points];
    private ObstacleField _field = null!;

    /// <summary>The main job's field, its grid filled, and the points.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var match = MatchBuilder.Build(ItemRegistry.Find("ball-grab")!.CreateScenario(1), seed: 1);
        match.Step(); // the snapshot is filled by the first cycle
        MatchSnapshot snapshot = match.Snapshot;
        _field = new ObstacleField(snapshot);
        var rng = new Random(28);
        for (int i = 0; i < Points; i++)
        {
            _points[i] = new Vector2((rng.NextSingle() - 0.5f) * snapshot.FieldLength, (rng.NextSingle() - 0.5f) * snapshot.FieldWidth);
        }

        for (float x = -snapshot.FieldLength / 2f; x <= snapshot.FieldLength / 2f; x += ObstacleField.Cell / 2f)
        {
            for (float z = -snapshot.FieldWidth / 2f; z <= snapshot.FieldWidth / 2f; z += ObstacleField.Cell / 2f)
            {
                _field.Clearance(new Vector2(x, z));
            }
        }
    }

    /// <summary>The library's exact signed clearance, per point.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Points)]
    public float Measured()
    {
        float sum = 0f;
        foreach (var p in _points)
        {
            sum += _field.Measure(p);
        }

        return sum;
    }

    /// <summary>The grid lookup, per point.</summary>
    [Benchmark(OperationsPerInvoke = Points)]
    public float Grid()
    {
        float sum = 0f;
        foreach (var p in _points)
        {
            sum += _field.Clearance(p);
        }

        return sum;
    }
}
