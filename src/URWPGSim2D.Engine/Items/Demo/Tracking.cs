using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// What a demo team knows of the match, kept across cycles: a <see cref="FishTrack"/> for each of
/// its fish, a <see cref="BallTrack"/> for each ball, the field's borders and obstacles and the way round
/// them (found once). <see cref="Observe"/> takes each cycle's views; <see cref="Restart"/> forgets the
/// tracks when the referee has placed every body afresh (a new half).
/// </summary>
internal sealed class Tracking
{
    private ObstacleField? _field;
    private Waypath? _ways;

    /// <summary>The track of each of the team's fish, in the order the strategy is given them.</summary>
    public FishTrack[] Fish { get; private set; } = [];

    /// <summary>The track of each ball, by ball index.</summary>
    public BallTrack[] Balls { get; private set; } = [];

    /// <summary>Forgets every track (the next <see cref="Observe"/> starts them from its views).</summary>
    public void Restart()
    {
        Fish = [];
        Balls = [];
    }

    /// <summary>Takes this cycle's views of the team's fish and of the balls; returns the cycle's surroundings.</summary>
    public Surroundings Observe(MatchSnapshot snapshot, ReadOnlySpan<int> fish)
    {
        if (Fish.Length != fish.Length)
        {
            Fish = new FishTrack[fish.Length];
        }

        if (Balls.Length != snapshot.Balls.Length)
        {
            Balls = new BallTrack[snapshot.Balls.Length];
        }

        for (int i = 0; i < Balls.Length; i++)
        {
            Balls[i].Update(snapshot.Balls[i]);
        }

        for (int k = 0; k < fish.Length; k++)
        {
            Fish[k].Update(snapshot.Fish[fish[k]]);
        }

        _field ??= new ObstacleField(snapshot);
        _ways ??= new Waypath(_field);
        return new Surroundings(_field, _ways);
    }
}
