using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.Rescue;

/// <summary>
/// The demo strategy of 急速救援. Rescuing, fish k takes ball k and pushes it with
/// <see cref="Pusher"/> along its route (<see cref="RescueRoutes"/>): ball 0 (bottom left) goes up
/// through the left gap, over the centre wall and down through the right gap; ball 1 the mirror way,
/// under the centre wall, after ball 0 has cleared the left gap (until then fish 1 pushes its ball
/// only to x = −1000). A fish far from its ball swims there through the gaps (<see cref="Waypath"/>).
/// A fish whose ball is rescued swims out of the other ball's way. Defending, the active fish guards the zone: it waits at (1300, 0) and
/// pushes any unrescued ball that comes right of the right gap (x &gt; 600) back toward the left at
/// a gentle speed (the parked fish cannot move). Positions are filtered (<see cref="FishTrack"/>,
/// <see cref="BallTrack"/>).
/// </summary>
internal sealed class RescueDemo(int team, RescueReferee referee) : IStrategy
{
    private const int PushVCode = 6;
    private const int ClearVCode = 3;
    private const float Ahead = 350f;

    private readonly RouteProgress[] _progress = new RouteProgress[2];
    private readonly Tracking _tracking = new();
    private Pusher[] _pushers = [];
    private int _half;

    /// <inheritdoc/>
    public string TeamName => "rescue demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_tracking.Fish.Length != fish.Length || referee.Half != _half)
        {
            // A new half: the referee has placed every body afresh.
            _half = referee.Half;
            _pushers = new Pusher[fish.Length];
            _tracking.Restart();
            Array.Clear(_progress);
        }

        var around = _tracking.Observe(snapshot, fish);
        bool rescuing = referee.Rescuer == team;
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            decisions[k] = rescuing ? Rescue(snapshot, me, k, around) : Defend(snapshot, me, k, around);
        }
    }

    private Decision Rescue(MatchSnapshot snapshot, in FishView me, int k, in Surroundings around)
    {
        int ball = BallOf(k);
        if (ball < 0)
        {
            return Rest(me, k, around);
        }

        float radius = snapshot.Balls[ball].Radius;
        ref BallTrack b = ref _tracking.Balls[ball];
        ReadOnlySpan<Vector2> route = RescueRoutes.Route(ball);
        if (ball == 1 && !referee.HasRescued(team, 0) && _tracking.Balls[0].Position.X < RescueRoutes.ClearX && b.Position.X > RescueRoutes.WaitX)
        {
            // Ball 1 waits on its route until ball 0 is through the left gap.
            return Decision.Stop;
        }

        Vector2 direction = _progress[ball].Direction(route, b.Position, Ahead);
        return _pushers[k].Push(me, _tracking.Fish[k], ref b, radius, direction, around, PushVCode);
    }

    // Fish k's ball (its own), or −1 once that is rescued (the other fish is on the other ball).
    private int BallOf(int k)
    {
        int own = Math.Min(k, 1);
        return referee.HasRescued(team, own) ? -1 : own;
    }

    // Out of the way of the other ball's last legs: the corner on this fish's own side, then stop.
    private Decision Rest(in FishView me, int k, in Surroundings around)
    {
        Vector2 spot = RescueRoutes.Rest(k);
        if (Vector2.Distance(_tracking.Fish[k].Position, spot) < 200f)
        {
            return Decision.Stop;
        }

        return _pushers[k].Travel(me, _tracking.Fish[k], spot, around);
    }

    // Defending: the active fish guards the zone from (1300, 0) and pushes any unrescued ball that
    // comes right of the right gap back toward it, gently.
    private Decision Defend(MatchSnapshot snapshot, in FishView me, int k, in Surroundings around)
    {
        int nearest = -1;
        float best = float.PositiveInfinity;
        for (int i = 0; i < snapshot.Balls.Length && i < 2; i++)
        {
            Vector2 p = _tracking.Balls[i].Position;
            if (referee.HasRescued(referee.Rescuer, i) || p.X <= RescueRoutes.GuardX)
            {
                continue;
            }

            float d = Vector2.Distance(_tracking.Fish[k].Position, p);
            if (d < best)
            {
                best = d;
                nearest = i;
            }
        }

        if (nearest < 0)
        {
            return Vector2.Distance(_tracking.Fish[k].Position, RescueRoutes.Guard) < 200f ? Decision.Stop : _pushers[k].Travel(me, _tracking.Fish[k], RescueRoutes.Guard, around, 6);
        }

        return _pushers[k].Push(me, _tracking.Fish[k], ref _tracking.Balls[nearest], snapshot.Balls[nearest].Radius, -Vector2.UnitX, around, ClearVCode);
    }
}
