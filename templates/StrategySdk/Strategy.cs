// The template of a team strategy in the strategy SDK (package URWPGSim2D.Strategies): one class
// implementing IStrategy, asked every 100 ms cycle for one decision per fish of the team.
// This example: every fish swims at the ball nearest to it, turning toward it.
using System;
using System.Numerics;
using URWPGSim2D.Strategies;

namespace MyTeam
{
    /// <summary>The team's strategy: the server creates one instance for the whole match.</summary>
    public sealed class Strategy : IStrategy
    {
        /// <summary>The team's name in summaries, traces, results and pages.</summary>
        public string TeamName => "My Team";

        /// <summary>Fills decisions[k] for the fish whose index is fish[k].</summary>
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

                Vector2 target = Nearest(snapshot.Balls, me.Position);
                Vector2 to = target - me.Position;
                // The heading error in (-pi, pi]: turn gear 0 is hard left, 7 straight, 14 hard right.
                float error = MathF.IEEERemainder(MathF.Atan2(to.Y, to.X) - me.Heading, 2f * MathF.PI);
                int turn = 7 + (int)MathF.Round(Math.Clamp(error / 0.6f, -1f, 1f) * 7f);
                int speed = MathF.Abs(error) < 0.6f ? 14 : 6;
                decisions[k] = new Decision(speed, turn);
            }
        }

        private static Vector2 Nearest(ReadOnlySpan<BallView> balls, Vector2 from)
        {
            Vector2 best = balls[0].Position;
            foreach (BallView ball in balls)
            {
                if (Vector2.DistanceSquared(ball.Position, from) < Vector2.DistanceSquared(best, from))
                    best = ball.Position;
            }

            return best;
        }
    }
}
