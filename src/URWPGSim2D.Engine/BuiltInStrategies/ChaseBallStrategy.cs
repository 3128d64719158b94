using URWPGSim2D.Engine.Items.Demo;
using URWPGSim2D.Engine.Teams;

namespace URWPGSim2D.Engine.BuiltInStrategies;

/// <summary>
/// Built-in <c>chase-ball</c>: each fish swims to the ball nearest to it and pushes it toward the
/// opponent's goal (team 0 attacks +X, team 1 attacks −X). It first heads for a point behind the
/// ball on the goal–ball line, then, once lined up, drives through the ball. It slows down to turn
/// tightly, and a fish that has not moved for two seconds (wedged against a wall) turns the other way
/// for a while: the steering and the escape are the demo strategies' (<see cref="Steering"/>,
/// <see cref="Stuck"/>). Deterministic: the only state is each fish's recent progress. It draws its
/// plan (<see cref="DebugDraw"/>, shown with <c>run --debug-draw</c>): per fish the route head → aim →
/// ball → goal, the target ball circled, the aim point and what it is doing (<c>line up</c>, <c>push</c>).
/// </summary>
public sealed class ChaseBallStrategy : IStrategy, IRestartable
{
    private const float LineUpAngle = 0.6f;
    private const int PlanColour = 0x2e8b57; // the planned route after the aim point
    private const int TargetColour = 0xffd400; // the target ball and the aim point

    private Stuck[] _stuck = [];

    /// <inheritdoc/>
    public string TeamName => "chase-ball";

    /// <inheritdoc/>
    void IRestartable.Restart()
    {
        Array.Clear(_stuck);
    }

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        var balls = snapshot.Balls;
        if (_stuck.Length != fish.Length)
        {
            _stuck = new Stuck[fish.Length];
        }

        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            if (balls.IsEmpty)
            {
                decisions[k] = Decision.Stop;
                continue;
            }

            Vector2 head = Steering.Head(me);
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
            decisions[k] = Steering.SwimTo(me, aim, linedUp ? 15 : 14); // through the ball at full speed
            if (DebugDraw.IsOn)
            {
                Vector2 goal = new(goalX, 0f);
                DebugDraw.Line(head, aim, me.Index);
                DebugDraw.Line(aim, ball.Position, me.Index, PlanColour);
                DebugDraw.Line(ball.Position, goal, me.Index, PlanColour);
                DebugDraw.Circle(ball.Position, ball.Radius + 12f, me.Index, TargetColour);
                DebugDraw.Point(aim, me.Index, TargetColour);
                DebugDraw.Text(aim + new Vector2(20f, -20f), linedUp ? "push" : "line up", me.Index);
            }
        }
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
}
