// <snippet>
using System;
using System.Numerics;
using URWPGSim2D.Strategies;

namespace MyTeam
{
    /// <summary>Every fish swims at the first ball, turning toward it.</summary>
    public sealed class TowardTheBall : IStrategy
    {
        public string TeamName => "toward the ball";

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

                Vector2 to = snapshot.Balls[0].Position - me.Position;
                float error = MathF.IEEERemainder(MathF.Atan2(to.Y, to.X) - me.Heading, 2f * MathF.PI);
                int turn = 7 + (int)MathF.Round(Math.Clamp(error / 0.5f, -1f, 1f) * 7f); // 0 left … 14 right
                decisions[k] = new Decision(MathF.Abs(error) < 0.5f ? 12 : 4, turn);
            }
        }
    }
}
// </snippet>
