using System;
using System.Numerics;
using URWPGSim2D.Server.Items.Demo;

namespace URWPGSim2D.Server.Items.Rescue;

/// <summary>
/// The demo strategy of 急速救援. Rescuing, fish k takes ball k (ball 0 starts near the bottom
/// wall, ball 1 near the top) and pushes it along a route through the slalom: into the left gap at
/// z = 0, round the centre wall on the ball's own side (z = ±1000), through the right gap and into
/// the zone; a fish far from its ball swims the route backwards first. A fish whose ball is rescued
/// takes the other one. Defending, the active fish pushes the nearest ball back toward the left
/// wall at a gentle speed (the parked fish cannot move).
/// </summary>
internal sealed class RescueDemo(int team, RescueReferee referee) : IStrategy
{
    private const float Reach = 220f;
    private readonly int[] _stage = [0, 0];
    private Stuck[] _stuck = [];
    private Dribble[] _dribble = [];
    private int _half = 1;

    /// <inheritdoc/>
    public string TeamName => "rescue demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_stuck.Length != fish.Length)
        {
            _stuck = new Stuck[fish.Length];
            _dribble = new Dribble[fish.Length];
        }

        if (referee.Half != _half)
        {
            _half = referee.Half;
            Array.Clear(_stage);
        }

        bool rescuing = referee.Rescuer == team;
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            decisions[k] = rescuing ? Rescue(snapshot, me, k) : Defend(snapshot, me);
        }
    }

    // The route of ball b (side s = +1 for the bottom ball 0, −1 for the top ball 1), ending in the zone.
    private static Vector2 Waypoint(int ball, int stage)
    {
        float s = ball == 0 ? 1f : -1f;
        return stage switch
        {
            0 => new Vector2(-850f, s * 150f),
            1 => new Vector2(-300f, 0f),
            2 => new Vector2(0f, s * 1000f),
            3 => new Vector2(300f, 0f),
            4 => new Vector2(900f, 0f),
            _ => new Vector2(2050f, 0f),
        };
    }

    private Decision Rescue(MatchSnapshot snapshot, in FishView me, int k)
    {
        int ball = k < 2 && !referee.HasRescued(team, k) ? k : !referee.HasRescued(team, 1 - Math.Min(k, 1)) ? 1 - Math.Min(k, 1) : -1;
        if (ball < 0)
        {
            return Decision.Stop;
        }

        BallView b = snapshot.Balls[ball];
        while (_stage[ball] < 5)
        {
            Vector2 wp = Waypoint(ball, _stage[ball]);
            if (Vector2.Distance(b.Position, wp) >= Reach && b.Position.X <= wp.X + 30f)
            {
                break;
            }

            _stage[ball]++;
        }

        int fishRegion = Region(me.Position.X), ballRegion = Region(b.Position.X);
        if (fishRegion > ballRegion && Vector2.Distance(me.Position, b.Position) > 500f)
        {
            return Steering.SwimTo(me, Back(me.Position, ball == 0 ? 1f : -1f));
        }

        return _dribble[k].Toward(me, b.Position, b.Radius, Waypoint(ball, _stage[ball]), 7, field: new Vector2(snapshot.FieldLength, snapshot.FieldWidth));
    }

    // The next point of the route backwards (toward the balls' start) from a position right of its ball.
    private static Vector2 Back(Vector2 p, float s)
    {
        return Region(p.X) switch
        {
            3 => p.X > 850f || MathF.Abs(p.Y) > 300f ? new Vector2(800f, 0f) : new Vector2(300f, 0f),
            2 => s * p.Y < 800f ? new Vector2(250f, s * 1000f) : new Vector2(-150f, s * 1000f),
            1 => p.X > -350f ? new Vector2(-400f, 0f) : new Vector2(-850f, 0f),
            _ => new Vector2(-1200f, 0f),
        };
    }

    // 0: left of the left gap, 1: between it and the centre wall, 2: between the centre wall and the right gap, 3: right of it.
    private static int Region(float x) => x < -550f ? 0 : x < 0f ? 1 : x < 550f ? 2 : 3;

    private Decision Defend(MatchSnapshot snapshot, in FishView me)
    {
        int nearest = -1;
        float best = float.PositiveInfinity;
        for (int i = 0; i < snapshot.Balls.Length; i++)
        {
            if (referee.HasRescued(referee.Rescuer, i))
            {
                continue;
            }

            float d = Vector2.Distance(me.Position, snapshot.Balls[i].Position);
            if (d < best)
            {
                best = d;
                nearest = i;
            }
        }

        if (nearest < 0)
        {
            return Decision.Stop;
        }

        BallView b = snapshot.Balls[nearest];
        return _dribble[0].Toward(me, b.Position, b.Radius, new Vector2(-2150f, b.Position.Y), pushVCode: 4, field: new Vector2(snapshot.FieldLength, snapshot.FieldWidth));
    }
}
