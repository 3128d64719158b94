// A test strategy in the style of the original's team strategies (written for this repository):
// every fish pushes the nearest ball toward the opponent's goal with StrategyHelper.Helpers.Dribble.
using System;
using System.Collections.Generic;
using System.Linq;
using System.Text;
using System.Drawing;
using xna = Microsoft.Xna.Framework;
using Microsoft.Xna.Framework;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;
using URWPGSim2D.StrategyHelper;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        public override object InitializeLifetimeService()
        {
            return null;
        }

        private Decision[] decisions = null;

        public int Calls;

        public string GetTeamName()
        {
            return "Dribbler";
        }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            if (decisions == null)
            {
                decisions = new Decision[mission.CommonPara.FishCntPerTeam];
            }
            Calls++;

            Field field = Field.Instance();
            bool left = mission.TeamsRef[teamId].Para.MyHalfCourt == HalfCourt.LEFT;
            xna.Vector3 goal = new xna.Vector3(left ? field.RightMm : field.LeftMm, 0, 0);
            for (int i = 0; i < mission.TeamsRef[teamId].Fishes.Count; i++)
            {
                RoboFish fish = mission.TeamsRef[teamId].Fishes[i];
                if (mission.EnvRef.Balls.Count == 0)
                {
                    decisions[i].VCode = 0;
                    decisions[i].TCode = 7;
                    continue;
                }
                Ball ball = mission.EnvRef.Balls[0];
                float best = float.MaxValue;
                foreach (Ball b in mission.EnvRef.Balls)
                {
                    float d = xna.Vector3.Distance(b.PositionMm, fish.PolygonVertices[0]);
                    if (d < best) { best = d; ball = b; }
                }
                xna.Vector3 toGoal = goal - ball.PositionMm;
                if (toGoal.Length() != 0) toGoal.Normalize();
                xna.Vector3 behind = ball.PositionMm - toGoal * (ball.RadiusMm + 20);
                float dir = xna.MathHelper.ToRadians(Helpers.GetAngleDegree(goal - ball.PositionMm));
                Helpers.Dribble(ref decisions[i], fish, behind, dir, 10, 30, 150, 14, 8, 15, mission.CommonPara.MsPerCycle, false);
            }
            return decisions;
        }
    }
}
