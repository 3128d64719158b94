// The template of a team strategy in the original URWPGSim2D API: the same class, interface and
// types as the original's strategies, so an existing strategy's source can replace this file as it is.
// This example plays 抢球博弈 (ball-grab): a ball scores its value (3, 2 or 1) for a team when it
// lies wholly inside the goal box at the team's OWN end (the end its fish start from; the ends swap
// at half time). A box opens only toward the end wall behind it, so each fish takes a ball its team
// has not scored and pushes it past the end of the box's bar, into the channel between the box and
// the end wall, and from there into the box. A fish caught inside a box swims out through its opening.
using System;
using System.Collections.Generic;
using System.Linq;
using System.Text;
using xna = Microsoft.Xna.Framework;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;
using URWPGSim2D.StrategyHelper;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        #region reserved code of the original (kept so old sources and this template look alike)
        public override object InitializeLifetimeService()
        {
            return null;
        }
        #endregion

        // The ball-grab field, mm, seen from the team's own end at +x (the left end is mirrored):
        // the box's back wall faces the field at x = 964, its two bars reach from x = 978 to 1152
        // at z = ±532 (50 mm wide), the end wall is at x = 1500.
        private const float BackX = 964, BoxOuterX = 1152, BarOuterZ = 557, EndX = 1500;

        // One instance lives for the whole match: fields keep state between cycles.
        private Decision[] decisions = null;
        private int[] target;         // the ball each fish pushes, -1 for none
        private int[] since;          // the cycle it took that ball
        private int[] restUntil;      // a ball left alone until this cycle
        private int cycle;

        public string GetTeamName()
        {
            return "My Team";
        }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            int fishCount = mission.CommonPara.FishCntPerTeam;
            List<Ball> balls = mission.EnvRef.Balls;
            if (decisions == null)
            {
                decisions = new Decision[fishCount];
                target = Enumerable.Repeat(-1, fishCount).ToArray();
                since = new int[fishCount];
                restUntil = new int[balls.Count];
            }

            cycle++;
            Team<RoboFish> me = mission.TeamsRef[teamId];
            // side: +1 when the team's own end (and box) is the right one; positions are mirrored by it.
            float side = me.Para.MyHalfCourt == HalfCourt.RIGHT ? 1 : -1;
            string end = side > 0 ? "Right" : "Left";

            for (int i = 0; i < me.Fishes.Count && i < decisions.Length; i++)
            {
                RoboFish fish = me.Fishes[i];
                int ball = Choose(mission, balls, fish, i, side, end);
                if (ball != target[i])
                {
                    target[i] = ball;
                    since[i] = cycle;
                }
                else if (ball >= 0 && cycle - since[i] > 600)
                {
                    // A minute on one ball: leave it alone for a minute and take another.
                    restUntil[ball] = cycle + 600;
                    target[i] = ball = Choose(mission, balls, fish, i, side, end);
                    since[i] = cycle;
                }

                xna.Vector3 p = fish.PositionMm;
                if (Math.Abs(p.X) > BackX - 20 && Math.Abs(p.X) < BoxOuterX + 40 && Math.Abs(p.Z) < BarOuterZ - 40)
                {
                    // Inside a box (open only toward its end wall): swim out through the opening first.
                    SwimTo(ref decisions[i], fish, new xna.Vector3(Math.Sign(p.X) * 1350, 0, p.Z), 4);
                    continue;
                }

                if (ball < 0)
                {
                    decisions[i].VCode = 0;
                    decisions[i].TCode = 7;
                    continue;
                }

                Push(ref decisions[i], fish, balls[ball], side);
            }

            return decisions;
        }

        // The ball for fish i: one its team has not scored yet, not another fish's, best worth the trip.
        private int Choose(Mission mission, List<Ball> balls, RoboFish fish, int i, float side, string end)
        {
            int best = -1;
            double bestWorth = 0;
            for (int b = 0; b < balls.Count; b++)
            {
                object scored = mission.HtMissionVariables["Ball_" + b + "_" + end + "_Status"];
                if ((scored != null && Convert.ToInt32(scored) == 1) || restUntil[b] > cycle || TakenByOther(b, i))
                {
                    continue;
                }

                Ball ball = balls[b];
                int value = ball.RadiusMm < 48 ? 3 : ball.RadiusMm < 68 ? 2 : 1;
                double worth = value / (xna.Vector3.Distance(ball.PositionMm, fish.PositionMm) + 300.0);
                if (Math.Abs(ball.PositionMm.X) > EndX - ball.RadiusMm - 40)
                {
                    worth /= 10; // against an end wall: no fish gets behind it there, so it is taken last
                }

                if (worth > bestWorth)
                {
                    best = b;
                    bestWorth = worth;
                }
            }

            return best;
        }

        private bool TakenByOther(int ball, int fish)
        {
            for (int k = 0; k < target.Length; k++)
            {
                if (k != fish && target[k] == ball)
                {
                    return true;
                }
            }

            return false;
        }

        // Pushes the ball one step along its route into the own box: a fish lined up behind the ball
        // (head behind it, facing the point 200 mm ahead on the route) swims through it; otherwise it
        // swims to a point behind the ball, going round the ball when the ball is in the way.
        private static void Push(ref Decision decision, RoboFish fish, Ball ball, float side)
        {
            float r = ball.RadiusMm;
            xna.Vector3 q = Mirror(ball.PositionMm, side);
            xna.Vector3 dir = Ahead(Route(q, r), 200) - q;
            if (dir.Length() < 1)
            {
                decision.VCode = 0;
                decision.TCode = 7;
                return;
            }

            dir.Normalize();
            xna.Vector3 head = Mirror(fish.PolygonVertices[0], side);
            xna.Vector3 toBall = q - head;
            float along = xna.Vector3.Dot(toBall, dir);
            float across = Math.Abs(toBall.X * dir.Z - toBall.Z * dir.X);
            float facing = (float)Math.Atan2(dir.Z, dir.X);
            float heading = side > 0 ? fish.BodyDirectionRad : xna.MathHelper.Pi - fish.BodyDirectionRad;
            if (along > -r * 0.5f && across < r * 0.8f && Math.Abs(xna.MathHelper.WrapAngle(facing - heading)) < 0.5f
                && toBall.Length() < r + 200)
            {
                int gear = q.X > BackX - 150 ? 4 : 6; // gently near the box
                SwimTo(ref decision, fish, Mirror(q + dir * r, side), gear);
                return;
            }

            xna.Vector3 aim = q - dir * (r + 90);
            xna.Vector3 me = Mirror(fish.PositionMm, side);
            if (xna.Vector3.Dot(q - me, aim - me) > 0 && (q - me).LengthSquared() < (aim - me).LengthSquared())
            {
                // The ball is between the fish and the point behind it: aim beside the ball first.
                xna.Vector3 across2 = new xna.Vector3(-dir.Z, 0, dir.X);
                float s = xna.Vector3.Dot(me - q, across2) >= 0 ? 1 : -1;
                aim = q + across2 * s * (r + 160) - dir * (r * 0.5f);
            }

            SwimTo(ref decision, fish, Mirror(Clamp(aim), side), 10);
        }

        // Turns toward the point (TCode 7 is straight on, higher turns toward a larger angle) and
        // swims at up to the given VCode, slower when the point is near or off to the side.
        private static void SwimTo(ref Decision decision, RoboFish fish, xna.Vector3 aim, int maxVCode)
        {
            xna.Vector3 to = aim - fish.PositionMm;
            float error = xna.MathHelper.WrapAngle((float)Math.Atan2(to.Z, to.X) - fish.BodyDirectionRad);
            decision.TCode = 7 + (int)Math.Round(Math.Max(-1, Math.Min(1, error / 0.4f)) * 7);
            int vcode = Math.Abs(error) > 1.2f ? 2 : Math.Abs(error) > 0.6f ? 4 : maxVCode;
            if (to.Length() < 250) vcode = Math.Min(vcode, 4);
            decision.VCode = vcode;
        }

        // The route of a ball at q (own end at +x) into the box: past the bar end on the ball's side,
        // round it into the channel, down the channel to beside the opening, into the box.
        private static List<xna.Vector3> Route(xna.Vector3 q, float r)
        {
            float s = q.Z >= 0 ? 1 : -1;
            var pastBar = new xna.Vector3(BackX - 150, 0, s * (BarOuterZ + r + 90));
            var channel = new xna.Vector3(1290, 0, s * (BarOuterZ + r + 110));
            var beside = new xna.Vector3(1240, 0, s * 380);
            var inside = new xna.Vector3(BackX + r, 0, s * 40);
            var route = new List<xna.Vector3> { q };
            if (q.X < BoxOuterX + r - 20)
            {
                if (q.X < pastBar.X && Math.Abs(q.Z) < Math.Abs(pastBar.Z) + 200)
                {
                    route.Add(pastBar);
                }

                route.Add(channel);
                route.Add(beside);
            }
            else if (Math.Abs(q.Z) > 440)
            {
                route.Add(beside);
            }

            route.Add(inside);
            return route;
        }

        // The point the given distance along the route from its start (its end when the route is shorter).
        private static xna.Vector3 Ahead(List<xna.Vector3> route, float distance)
        {
            for (int k = 1; k < route.Count; k++)
            {
                float leg = xna.Vector3.Distance(route[k - 1], route[k]);
                if (leg >= distance)
                {
                    return route[k - 1] + (route[k] - route[k - 1]) * (distance / leg);
                }

                distance -= leg;
            }

            return route[route.Count - 1];
        }

        private static xna.Vector3 Mirror(xna.Vector3 v, float side)
        {
            return new xna.Vector3(v.X * side, v.Y, v.Z);
        }

        // Keeps a point for the fish inside the field (3000 x 2000).
        private static xna.Vector3 Clamp(xna.Vector3 v)
        {
            return new xna.Vector3(Math.Max(-1440, Math.Min(1440, v.X)), 0, Math.Max(-940, Math.Min(940, v.Z)));
        }
    }
}
