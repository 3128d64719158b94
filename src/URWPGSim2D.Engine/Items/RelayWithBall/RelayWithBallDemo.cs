using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.RelayWithBall;

/// <summary>
/// The demo strategy of 带球接力: fish 0 carries the ball on legs 1 and 3 (out of the left pocket, up,
/// along the top channel, down and into the right pocket), fish 1 on legs 2 and 4 (the mirror way
/// along the bottom channel); the other fish waits in a corner of its own end, off the ball's way.
/// The ball starts wedged in the left pocket's corner, so fish 0 first pushes it up and to the left,
/// sliding it along the arm, until it is clear of the post.
/// </summary>
internal sealed class RelayWithBallDemo(RelayWithBallReferee referee) : IStrategy
{
    private const int PushVCode = 6;
    private const float Ahead = 300f;

    private static readonly Vector2[] Top = [new(-450f, 0f), new(-950f, 0f), new(-950f, -800f), new(950f, -800f), new(950f, 0f), new(450f, 0f)];
    private static readonly Vector2[] Bottom = [new(450f, 0f), new(950f, 0f), new(950f, 800f), new(-950f, 800f), new(-950f, 0f), new(-450f, 0f)];
    private static readonly Vector2[] Waits = [new(-1300f, -650f), new(1300f, 650f)];

    // Up and to the left: slides the wedged ball along the arm above it, out of the corner.
    private static readonly Vector2 Unwedge = Vector2.Normalize(new Vector2(-0.35f, -0.94f));

    private readonly Tracking _tracking = new();
    private readonly Pusher[] _pushers = new Pusher[2];
    private readonly Dribble[] _dribbles = new Dribble[2];
    private readonly Stuck[] _stuck = new Stuck[2];
    private RouteProgress _route;
    private int _leg = -1;

    /// <inheritdoc/>
    public string TeamName => "relay-with-ball demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        var around = _tracking.Observe(snapshot, fish);
        int legs = referee.Legs;
        if (legs != _leg)
        {
            _leg = legs;
            _route = default;
        }

        ref BallTrack ball = ref _tracking.Balls[0];
        int carrier = legs % 2;
        Vector2 way = legs == 0 && ball.Position.X > -420f && ball.Position.Y < -200f
            ? Unwedge
            : _route.Direction(carrier == 0 ? Top : Bottom, ball.Position, Ahead);
        for (int k = 0; k < 2 && k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
            }
            else if (k == carrier && legs < 4 && MathF.Abs(ball.Position.Y) < 600f)
            {
                decisions[k] = _pushers[k].Push(me, _tracking.Fish[k], ref ball, snapshot.Balls[0].Radius, way, around, PushVCode);
            }
            else if (k == carrier && legs < 4)
            {
                decisions[k] = _dribbles[k].Toward(me, ball.Position, snapshot.Balls[0].Radius, ball.Position + (way * 500f), PushVCode, new Vector2(snapshot.FieldLength, snapshot.FieldWidth));
            }
            else
            {
                decisions[k] = Vector2.Distance(_tracking.Fish[k].Position, Waits[k]) < 200f ? Decision.Stop : _pushers[k].Travel(me, _tracking.Fish[k], Waits[k], around, 6);
            }
        }
    }
}
