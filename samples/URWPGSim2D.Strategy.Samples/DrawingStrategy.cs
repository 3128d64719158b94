// <snippet>
using System;
using System.Numerics;
using URWPGSim2D.Strategies;

namespace MyTeam
{
    /// <summary>Swims at the first ball and draws its plan: a line to the ball, the ball circled, what it does.</summary>
    public sealed class DrawsItsPlan : IStrategy
    {
        public string TeamName => "draws its plan";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            for (int k = 0; k < fish.Length; k++)
            {
                FishView me = snapshot.Fish[fish[k]];
                if (snapshot.Balls.IsEmpty)
                {
                    decisions[k] = Decision.Stop;
                    continue;
                }

                Vector2 target = snapshot.Balls[0].Position;
                Vector2 to = target - me.Position;
                float error = MathF.IEEERemainder(MathF.Atan2(to.Y, to.X) - me.Heading, 2f * MathF.PI);
                int turn = 7 + (int)MathF.Round(Math.Clamp(error / 0.5f, -1f, 1f) * 7f);
                decisions[k] = new Decision(MathF.Abs(error) < 0.5f ? 12 : 4, turn);

                // Recorded with run --debug-draw; otherwise each call returns at once.
                DebugDraw.Line(me.Position, target, me.Index);
                DebugDraw.Circle(target, snapshot.Balls[0].Radius + 10f, me.Index, 0xffd400);
                if (DebugDraw.IsOn) // build a text only when it is recorded
                {
                    DebugDraw.Text(me.Position, $"error {error:0.00} rad", me.Index);
                }
            }
        }
    }
}
// </snippet>
