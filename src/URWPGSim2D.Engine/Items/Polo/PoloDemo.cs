using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Engine.Items.Demo;
using URWPGSim2D.Engine.Teams;

namespace URWPGSim2D.Engine.Items.Polo;

/// <summary>
/// The demo strategy of water polo. One fish goes for the ball and pushes it into the goal the team
/// attacks now; in 3v3 and 5v5 fish 0 keeps goal (on a line 150 mm in front of its goal mouth,
/// level with the ball, never inside the goal), and the others hold places between ball and goal.
/// In 5v5 the attacker is the nearest of the fish allowed where the ball is (defenders 1, 2 in the
/// own half, forwards 3, 4 in the other). During penalties only fish 0 plays.
/// </summary>
internal sealed class PoloDemo(int team, PoloReferee referee) : IStrategy, IRestartable
{
    private Stuck[] _stuck = [];
    private Dribble[] _dribble = [];

    /// <inheritdoc/>
    public string TeamName => "water-polo demo";

    /// <inheritdoc/>
    void IRestartable.Restart()
    {
        Array.Clear(_stuck);
        Array.Clear(_dribble);
    }

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_stuck.Length != fish.Length)
        {
            _stuck = new Stuck[fish.Length];
            _dribble = new Dribble[fish.Length];
        }

        int side = referee.AttackSide(team);
        float end = snapshot.FieldLength / 2f;
        BallView ball = snapshot.Balls[0];
        Vector2 goal = new(side * (end + 20f), 0f);
        int attacker = ChooseAttacker(snapshot, fish, side, ball.Position);
        Vector2 field = new(snapshot.FieldLength, snapshot.FieldWidth);
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (referee.SentOffCycles(fish[k]) > 0 || (referee.Kicker >= 0 && k > 0))
            {
                decisions[k] = Decision.Stop;
                continue;
            }

            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            if (k == attacker)
            {
                // Aim between the posts; near the goal, straight into it.
                Vector2 aim = MathF.Abs(ball.Position.X - goal.X) < 500f ? goal : new Vector2(side * (end - 300f), 0f);
                decisions[k] = _dribble[k].Toward(me, ball.Position, ball.Radius, aim, 7, field);
            }
            else if (k == 0)
            {
                // Keeper: level with the ball, in front of its own goal mouth.
                float x = -side * (end - Field.GoalDepth - 150f);
                float z = Math.Clamp(ball.Position.Y, -Field.GoalWidth / 2f, Field.GoalWidth / 2f);
                decisions[k] = Dribble.Swim(me, new Vector2(x, z), 6);
            }
            else
            {
                // Support: a place between the ball and the own goal, spread by fish number.
                float own = -side * end;
                float x = (ball.Position.X * 0.5f) + (own * 0.3f);
                if (fish.Length == 5)
                {
                    x = k <= 2 ? -side * MathF.Max(300f, MathF.Abs(x)) : side * 350f;
                }

                float z = ((k % 2 == 0) ? 1f : -1f) * 350f;
                decisions[k] = Dribble.Swim(me, new Vector2(x, z), 6);
            }
        }
    }

    private int ChooseAttacker(MatchSnapshot snapshot, ReadOnlySpan<int> fish, int side, Vector2 ball)
    {
        if (fish.Length == 1 || referee.Kicker >= 0)
        {
            return 0;
        }

        int best = -1;
        float bestDistance = float.PositiveInfinity;
        for (int k = 1; k < fish.Length; k++)
        {
            if (referee.SentOffCycles(fish[k]) > 0)
            {
                continue;
            }

            if (fish.Length == 5 && (k <= 2 ? ball.X * side > 150f : ball.X * side < -150f))
            {
                continue;
            }

            float d = Vector2.Distance(snapshot.Fish[fish[k]].Position, ball);
            if (d < bestDistance)
            {
                bestDistance = d;
                best = k;
            }
        }

        return best < 0 ? 0 : best;
    }
}
