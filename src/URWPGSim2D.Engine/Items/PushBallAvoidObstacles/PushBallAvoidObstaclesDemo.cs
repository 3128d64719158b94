using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.PushBallAvoidObstacles;

/// <summary>
/// The demo strategy of 带球避障: for the first two legs the fish swims through the open passages
/// (below the left wall, above the right one); then it pushes the ball back along the same way —
/// up through the right passage, across, down through the left passage — until the ball is past
/// the black line.
/// </summary>
internal sealed class PushBallAvoidObstaclesDemo(PushBallAvoidObstaclesReferee referee) : IStrategy
{
    private const float Reached = 150f;

    // Through the left passage (z −790, below the line at z −510), then the right one (z 790).
    private static readonly Vector2[] SwimRoute = [new(-900f, -790f), new(-250f, -790f), new(-200f, 750f), new(850f, 790f)];

    // The ball's way back: up to the right passage, through it, across and through the left one.
    private static readonly Vector2[] PushRoute = [PushBallAvoidObstaclesLayout.BallStart, new(850f, 760f), new(150f, 760f), new(-150f, -760f), new(-900f, -760f)];

    private int _waypoint;
    private Stuck _stuck;
    private Dribble _dribble;
    private RouteProgress _route;

    /// <inheritdoc/>
    public string TeamName => "push-ball-avoid-obstacles demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        FishView me = snapshot.Fish[fish[0]];
        if (_stuck.Escaping(me, out Decision escape))
        {
            decisions[0] = escape;
            return;
        }

        if (referee.Legs < 2)
        {
            // The next waypoint ahead (a fish put back after a foul skips those behind it).
            while (_waypoint < SwimRoute.Length - 1
                && (Vector2.Distance(me.Position, SwimRoute[_waypoint]) < Reached || SwimRoute[_waypoint].X < me.Position.X - 50f))
            {
                _waypoint++;
            }

            decisions[0] = Dribble.Swim(me, SwimRoute[_waypoint], 3);
            return;
        }

        BallView ball = snapshot.Balls[0];
        Vector2 way = _route.Direction(PushRoute, ball.Position, 250f);
        Vector2 target = ball.Position + (way * 500f);
        decisions[0] = _dribble.Toward(me, ball.Position, ball.Radius, target, 6, new Vector2(snapshot.FieldLength, snapshot.FieldWidth));
    }
}
