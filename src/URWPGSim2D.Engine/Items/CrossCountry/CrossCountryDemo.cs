using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.CrossCountry;

/// <summary>
/// The demo strategy of 障碍越野: the fish pushes the ball of the current step to its target along
/// the wall it lies by (ball 0 along the top, ball 1 along the bottom), above or below the blocks
/// on x = 0 (between them and the posts), slowing down for the last half metre so the ball stops
/// within the 22 mm.
/// </summary>
internal sealed class CrossCountryDemo(CrossCountryReferee referee) : IStrategy
{
    private Stuck _stuck;
    private Dribble _dribble;

    /// <inheritdoc/>
    public string TeamName => "cross-country demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        FishView me = snapshot.Fish[fish[0]];
        if (referee.Step >= 4)
        {
            decisions[0] = Decision.Stop;
            return;
        }

        if (_stuck.Escaping(me, out Decision escape))
        {
            decisions[0] = escape;
            return;
        }

        int ball = referee.CurrentBall;
        BallView b = snapshot.Balls[ball];
        Vector2 target = CrossCountryLayout.Targets[ball];
        float s = ball == 0 ? -1f : 1f;

        // Between the inner block (|z| from 1000 to 1100) and the post at the centre: the lane |z| ≈ 700.
        Vector2 aim = b.Position.X < -300f ? new Vector2(-150f, s * 700f)
            : b.Position.X < 300f ? new Vector2(450f, s * 700f)
            : target;
        bool last = aim == target && Vector2.Distance(b.Position, target) < 500f;
        decisions[0] = _dribble.Toward(me, b.Position, b.Radius, aim, last ? 3 : 6, new Vector2(snapshot.FieldLength, snapshot.FieldWidth));
    }
}
