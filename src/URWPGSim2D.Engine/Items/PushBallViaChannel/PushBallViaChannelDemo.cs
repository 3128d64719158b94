using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.PushBallViaChannel;

/// <summary>
/// The demo strategy of 协作过孔: the ball is led along a lane through the three channels (above the
/// right wall, below the middle one, above the left one) into the left goal. In each stage the fish
/// that has not yet touched the ball pushes it (fish 0 first), so both touch it before it passes the
/// stage's line; the other fish swims behind the ball along the lane, out of the way.
/// </summary>
internal sealed class PushBallViaChannelDemo(PushBallViaChannelReferee referee) : IStrategy
{
    // The ball's lane: up to the right channel, down between the right and middle walls, through the
    // middle channel, up again, through the left channel and down into the goal mouth.
    private static readonly Vector2[] Lane =
    [
        PushBallViaChannelLayout.BallStart, new(1000f, -800f), new(340f, -800f), new(340f, 800f),
        new(-340f, 800f), new(-340f, -800f), new(-1000f, -800f), new(-1150f, 0f), new(-1480f, 0f),
    ];

    private const int PushVCode = 6;
    private const float Ahead = 300f;

    private readonly Tracking _tracking = new();
    private readonly Pusher[] _pushers = new Pusher[2];
    private RouteProgress _route;

    /// <inheritdoc/>
    public string TeamName => "push-ball-via-channel demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        var around = _tracking.Observe(snapshot, fish);
        ref BallTrack ball = ref _tracking.Balls[0];
        float radius = snapshot.Balls[0].Radius;
        Vector2 way = _route.Direction(Lane, ball.Position, Ahead);
        int stage = referee.Stage;
        int pusher = !referee.Touched(0, stage) || referee.Touched(1, stage) ? 0 : 1;
        for (int k = 0; k < 2 && k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (k == pusher)
            {
                decisions[k] = _pushers[k].Push(me, _tracking.Fish[k], ref ball, radius, way, around, PushVCode);
                continue;
            }

            // Wait behind the ball on the lane, out of the pusher's way.
            Vector2 wait = ball.Position - (way * 700f);
            decisions[k] = Vector2.Distance(_tracking.Fish[k].Position, wait) < 200f ? Decision.Stop : _pushers[k].Travel(me, _tracking.Fish[k], wait, around, 6);
        }
    }
}
