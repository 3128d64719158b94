using System;
using System.Numerics;
using URWPGSim2D.Server.Items.Demo;
using URWPGSim2D.Strategies;
using static URWPGSim2D.Server.Items.BallGrab.BallGrabLayout;

namespace URWPGSim2D.Server.Items.BallGrab;

/// <summary>
/// The demo strategy of 抢球博弈. Each fish takes the ball its team has not scored yet that is best
/// worth the trip (value over distance, the two fish on different balls) and brings it into the
/// team's box in legs: a box only opens toward its end wall, so a ball in the field is pushed
/// round the end of a bar into the channel between the box and the wall, up the channel to a
/// staging point beside the opening, and from there diagonally into the box; a fish caught inside
/// a box first swims out through the opening. Works in a frame
/// where the team's box is at +x (mirrored for the left end).
/// </summary>
internal sealed class BallGrabDemo(BallGrabReferee referee) : IStrategy
{
    private int[] _target = [];
    private Stuck[] _stuck = [];

    /// <inheritdoc/>
    public string TeamName => "ball-grab demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_target.Length != fish.Length)
        {
            _target = new int[fish.Length];
            _stuck = new Stuck[fish.Length];
            Array.Fill(_target, -1);
        }

        int team = snapshot.Fish[fish[0]].Team;
        int side = referee.BoxSide(team);
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            FishView mine = me with { Position = new Vector2(me.Position.X * side, me.Position.Y), Heading = side > 0 ? me.Heading : Steering.Wrap(MathF.PI - me.Heading) };
            if (BoxExit(mine, out Vector2 exit))
            {
                Decision e = Steering.SwimTo(mine, exit, 4);
                decisions[k] = side > 0 ? e : new Decision(e.VCode, 14 - e.TCode);
                continue;
            }

            int ball = Choose(snapshot, me, team, side, k);
            _target[k] = ball;
            if (ball < 0)
            {
                decisions[k] = Steering.SwimTo(me, new Vector2(0f, 0f), 6);
                continue;
            }

            BallView b = snapshot.Balls[ball];
            Vector2 q = new(b.Position.X * side, b.Position.Y);
            Vector2 leg = NextLeg(q, b.Radius);
            Decision d = Steering.Push(mine, q, b.Radius, leg, pushVCode: 10, approachVCode: 10);
            decisions[k] = side > 0 ? d : new Decision(d.VCode, 14 - d.TCode);
        }
    }

    // A fish inside either box (a U open toward its end wall, too short for the fish to turn in
    // across it) whose head points at the back wall swims along the back wall first and then out
    // through the opening; without this it stays pressed against the back wall trying to reach the field.
    private static bool BoxExit(in FishView me, out Vector2 exit)
    {
        float ax = MathF.Abs(me.Position.X), sx = me.Position.X >= 0f ? 1f : -1f;
        exit = default;
        if (ax < BackX - 20f || ax > BoxOuterX + 40f || MathF.Abs(me.Position.Y) > BoxHalfWidth + 10f)
        {
            return false;
        }

        float outward = MathF.Cos(me.Heading) * sx; // > 0: facing the opening
        float sz = me.Position.Y >= 0f ? 1f : -1f;
        exit = outward > 0.5f
            ? new Vector2(sx * (HalfLength - 150f), me.Position.Y)
            : new Vector2(sx * (BoxInnerX + 80f), sz * (BoxHalfWidth - 40f)) + (new Vector2(sx * 150f, 0f) * MathF.Max(0f, outward + 0.5f));
        return true;
    }

    // Where the ball should go next, in the frame with the team's box at +x.
    private static Vector2 NextLeg(Vector2 q, float radius)
    {
        float sign = q.Y >= 0f ? 1f : -1f;
        if (q.X > BoxOuterX)
        {
            // In the channel: beside the opening, push diagonally in; farther along, bring it closer.
            return MathF.Abs(q.Y) <= BoxHalfWidth ? new Vector2(BoxInnerX + 40f, -sign * 250f) : new Vector2(1250f, sign * 380f);
        }

        if (q.X > BackX - 120f && MathF.Abs(q.Y) < BarZ + radius + 40f)
        {
            // Behind the box's back wall or in the box already: round the bar end first.
            return new Vector2(BoxOuterX + 60f, sign * (BarZ + radius + 110f));
        }

        // In the field: to a point past the bar end on the ball's side, then into the channel.
        return new Vector2(BoxOuterX + 110f, sign * (BarZ + radius + 90f));
    }

    // The unscored ball with the best value per metre, not in the box already, not the partner's.
    private int Choose(MatchSnapshot snapshot, in FishView me, int team, int side, int k)
    {
        var balls = snapshot.Balls;
        int best = -1;
        float bestScore = float.NegativeInfinity;
        for (int i = 0; i < balls.Length; i++)
        {
            if (referee.HasScored(team, i) || InBox(balls[i].Position, balls[i].Radius, side) || Taken(i, k))
            {
                continue;
            }

            float value = (float)referee.BallValue(i);
            float distance = Vector2.Distance(me.Position, balls[i].Position) + 200f;
            float score = (value / distance) + (i == _target[k] ? 0.0015f : 0f);
            if (score > bestScore)
            {
                bestScore = score;
                best = i;
            }
        }

        return best;
    }

    private bool Taken(int ball, int k)
    {
        for (int j = 0; j < _target.Length; j++)
        {
            if (j != k && _target[j] == ball)
            {
                return true;
            }
        }

        return false;
    }
}
