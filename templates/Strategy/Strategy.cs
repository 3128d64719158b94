// The template of a team strategy in the original URWPGSim2D API: the same class, interface and
// types as the original's strategies, so an existing strategy's source can replace this file as it is.
// This example: fish 0 pushes the ball nearest to it toward the opponent's goal with
// StrategyHelper.Helpers.Dribble; the other fish guard their own goal mouth.
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

        // One instance lives for the whole match: fields keep state between cycles.
        private Decision[] decisions = null;

        public string GetTeamName()
        {
            return "My Team";
        }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            if (decisions == null)
            {
                decisions = new Decision[mission.CommonPara.FishCntPerTeam];
            }

            Team<RoboFish> me = mission.TeamsRef[teamId];
            Field field = mission.EnvRef.FieldInfo;
            bool onLeft = me.Para.MyHalfCourt == HalfCourt.LEFT;
            float attackX = onLeft ? field.RightMm : field.LeftMm;
            float defendX = onLeft ? field.LeftMm + field.GoalDepthMm + 150 : field.RightMm - field.GoalDepthMm - 150;

            for (int i = 0; i < me.Fishes.Count && i < decisions.Length; i++)
            {
                RoboFish fish = me.Fishes[i];
                if (i == 0 && mission.EnvRef.Balls.Count > 0)
                {
                    Ball ball = Nearest(mission.EnvRef.Balls, fish.PolygonVertices[0]);
                    xna.Vector3 goal = new xna.Vector3(attackX, 0, 0);
                    xna.Vector3 push = goal - ball.PositionMm;
                    if (push.Length() > 0) push.Normalize();
                    // Aim at a point just behind the ball on the ball–goal line, facing the goal.
                    xna.Vector3 behind = ball.PositionMm - push * (ball.RadiusMm + 30);
                    float facing = xna.MathHelper.ToRadians(Helpers.GetAngleDegree(push));
                    Helpers.Dribble(ref decisions[i], fish, behind, facing, 8, 30, 200, 14, 6, 10, mission.CommonPara.MsPerCycle, false);
                }
                else
                {
                    // Guard: hold a point in front of the own goal, facing the field.
                    float z = Math.Max(-field.GoalWidthMm / 2, Math.Min(field.GoalWidthMm / 2, (i % 2 == 0 ? 1 : -1) * 100));
                    xna.Vector3 post = new xna.Vector3(defendX, 0, z);
                    float facing = onLeft ? 0 : xna.MathHelper.Pi;
                    if (xna.Vector3.Distance(post, fish.PositionMm) < 60)
                    {
                        decisions[i].VCode = 0;
                        decisions[i].TCode = 7;
                    }
                    else
                    {
                        Helpers.Dribble(ref decisions[i], fish, post, facing, 10, 40, 150, 8, 3, 10, mission.CommonPara.MsPerCycle, true);
                    }
                }
            }

            return decisions;
        }

        private static Ball Nearest(List<Ball> balls, xna.Vector3 from)
        {
            Ball best = balls[0];
            foreach (Ball b in balls)
            {
                if (xna.Vector3.DistanceSquared(b.PositionMm, from) < xna.Vector3.DistanceSquared(best.PositionMm, from))
                {
                    best = b;
                }
            }
            return best;
        }
    }
}
