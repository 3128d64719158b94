using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.FourTeams;

/// <summary>
/// The demo strategy of 4支队伍测试: every fish of the team pushes the ball toward the wall across
/// the pool from its team's side (team 0 toward +x, 1 toward −x, 2 toward +z, 3 toward −z).
/// </summary>
internal sealed class FourTeamsDemo(int team) : IStrategy
{
    private static readonly Vector2[] Targets = [new(1500f, 0f), new(-1500f, 0f), new(0f, 1000f), new(0f, -1000f)];

    private Dribble[] _dribbles = [];
    private Stuck[] _stuck = [];

    /// <inheritdoc/>
    public string TeamName => "four-teams demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_dribbles.Length != fish.Length)
        {
            _dribbles = new Dribble[fish.Length];
            _stuck = new Stuck[fish.Length];
        }

        BallView ball = snapshot.Balls[0];
        Vector2 field = new(snapshot.FieldLength, snapshot.FieldWidth);
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            decisions[k] = _stuck[k].Escaping(me, out Decision escape)
                ? escape
                : _dribbles[k].Toward(me, ball.Position, ball.Radius, Targets[team % Targets.Length], 8, field);
        }
    }
}
