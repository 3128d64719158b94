using System;
using System.Numerics;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// Built-in <c>chase-ball</c>: each fish swims to the ball nearest to it and pushes it toward the
/// opponent's goal (team 0 attacks +X, team 1 attacks −X). It first heads for a point behind the
/// ball on the goal–ball line, then, once lined up, drives through the ball. It slows down to turn
/// tightly, and a fish that has not moved for two seconds (wedged against a wall) turns the other way
/// for a while. Deterministic: the only state is each fish's recent progress.
/// </summary>
internal sealed class ChaseBallStrategy : IStrategy
{
    private const float LineUpAngle = 0.6f;
    private const int StuckCycles = 20;
    private const int EscapeCycles = 25;

    private System.Numerics.Vector2[] _anchor = [];
    private int[] _still = [];
    private int[] _escape = [];

    /// <inheritdoc/>
    public string TeamName => "chase-ball";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        var balls = snapshot.Balls;
        if (_still.Length != fish.Length)
        {
            _anchor = new Vector2[fish.Length];
            _still = new int[fish.Length];
            _escape = new int[fish.Length];
        }

        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (Escaping(k, me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            if (balls.IsEmpty)
            {
                decisions[k] = Decision.Stop;
                continue;
            }

            Vector2 head = me.Position + (Direction(me.Heading) * ((me.BodyLength * 0.5f) + me.HeadLength));
            int nearest = 0;
            float best = float.PositiveInfinity;
            for (int b = 0; b < balls.Length; b++)
            {
                float d = Vector2.DistanceSquared(head, balls[b].Position);
                if (d < best)
                {
                    best = d;
                    nearest = b;
                }
            }

            BallView ball = balls[nearest];
            float goalX = me.Team == 0 ? snapshot.FieldLength * 0.5f : -snapshot.FieldLength * 0.5f;
            Vector2 toGoal = new Vector2(goalX, 0f) - ball.Position;
            toGoal = toGoal.LengthSquared() > 1e-6f ? Vector2.Normalize(toGoal) : new Vector2(me.Team == 0 ? 1f : -1f, 0f);
            Vector2 behind = ball.Position - (toGoal * (ball.Radius + 100f));
            Vector2 toBall = ball.Position - head;
            bool linedUp = Vector2.Dot(toBall, toGoal) > 0f && AngleBetween(toBall, toGoal) < LineUpAngle
                && Vector2.Distance(me.Position, behind) < 260f;
            Vector2 aim = linedUp ? ball.Position + (toGoal * ball.Radius) : behind;
            decisions[k] = Steer(me, aim, linedUp);
        }
    }

    // Counts cycles without progress; once stuck, turns hard the other way for a while.
    private bool Escaping(int k, in FishView me, out Decision escape)
    {
        escape = default;
        if (_escape[k] > 0)
        {
            _escape[k]--;
            escape = new Decision(3, me.AngularSpeed > 0f ? 0 : 14);
            return true;
        }

        if (Vector2.DistanceSquared(me.Position, _anchor[k]) > 40f * 40f)
        {
            _anchor[k] = me.Position;
            _still[k] = 0;
            return false;
        }

        if (++_still[k] < StuckCycles)
        {
            return false;
        }

        _still[k] = 0;
        _escape[k] = EscapeCycles;
        escape = new Decision(3, me.AngularSpeed > 0f ? 0 : 14);
        return true;
    }

    private static Decision Steer(in FishView me, Vector2 aim, bool pushing)
    {
        Vector2 to = aim - me.Position;
        float error = WrapAngle(MathF.Atan2(to.Y, to.X) - me.Heading);
        int tcode = 7 + (int)MathF.Round(Math.Clamp(error / 0.4f, -1f, 1f) * 7f);
        float distance = to.Length();
        float absError = MathF.Abs(error);

        // Slow enough that the turning circle (radius v/ω, ω ≈ 0.3 rad/s) reaches the aim point:
        // a circle through the fish tangent to its heading meets the point when r ≤ d / (2·sin e).
        float sine = absError >= MathF.PI / 2f ? 1f : MathF.Max(MathF.Sin(absError), 0.05f);
        float fastest = 0.3f * distance / (2f * sine);
        int vcode = 1;
        for (int v = pushing ? 15 : 14; v >= 1; v--)
        {
            if (Simulation.Kinematics.SpeedTable.TargetSpeed(v) <= fastest)
            {
                vcode = v;
                break;
            }
        }

        return new Decision(vcode, tcode);
    }

    private static float AngleBetween(Vector2 a, Vector2 b)
    {
        float la = a.Length();
        float lb = b.Length();
        if (la <= 0f || lb <= 0f)
        {
            return 0f;
        }

        return MathF.Acos(Math.Clamp(Vector2.Dot(a, b) / (la * lb), -1f, 1f));
    }

    private static Vector2 Direction(float heading) => new(MathF.Cos(heading), MathF.Sin(heading));

    private static float WrapAngle(float angle)
    {
        float a = MathF.IEEERemainder(angle, 2f * MathF.PI);
        return a >= MathF.PI ? a - (2f * MathF.PI) : a;
    }
}
