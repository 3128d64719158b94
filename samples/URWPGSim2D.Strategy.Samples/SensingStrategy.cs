// <snippet>
using System;
using System.Numerics;
using URWPGSim2D.Strategies;

namespace MyTeam
{
    /// <summary>
    /// Every fish swims at the ball nearest its head when the way there is clear, and round what is
    /// in the way (a fish, an obstacle, another ball) when it is not.
    /// </summary>
    public sealed class LookBeforeSwimming : IStrategy
    {
        private readonly FieldSensor _sensor = new();

        public string TeamName => "look before swimming";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            _sensor.Observe(snapshot); // once a cycle: the queries answer about this snapshot
            for (int k = 0; k < fish.Length; k++)
            {
                FishView me = snapshot.Fish[fish[k]];
                Vector2 forward = new(MathF.Cos(me.Heading), MathF.Sin(me.Heading));
                Vector2 head = me.Position + (forward * (me.BodyLength / 2 + me.HeadLength));
                SensedDistance ball = _sensor.Nearest(head, SensedKinds.Balls);
                if (!ball.Body.Exists)
                {
                    decisions[k] = Decision.Stop;
                    continue;
                }

                // The first body between the head and the ball, passing through the fish itself.
                Vector2 target = ball.Result.PointA;
                SensedHit first = _sensor.RayCast(head, target, SensedKinds.All, SensedBody.Fish(me.Index));
                if (first.Hit && first.Body != ball.Body)
                {
                    // Something is in the way: aim beside it, on the side with more room.
                    Vector2 side = new(-forward.Y, forward.X);
                    Vector2 left = first.Result.Point + (side * 200f), right = first.Result.Point - (side * 200f);
                    target = _sensor.Clearance(left) > _sensor.Clearance(right) ? left : right;
                }

                Vector2 to = target - me.Position;
                float error = MathF.IEEERemainder(MathF.Atan2(to.Y, to.X) - me.Heading, 2f * MathF.PI);
                int turn = 7 + (int)MathF.Round(Math.Clamp(error / 0.5f, -1f, 1f) * 7f); // 0 left … 14 right
                decisions[k] = new Decision(MathF.Abs(error) < 0.5f ? 10 : 4, turn);
            }
        }
    }
}
// </snippet>
