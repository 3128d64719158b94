// <snippet>
using System;
using xna = Microsoft.Xna.Framework;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;
using URWPGSim2D.StrategyHelper;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        public override object InitializeLifetimeService() { return null; }

        private Decision[] decisions = null;

        public string GetTeamName() { return "Ball pushers"; }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            if (decisions == null)
            {
                decisions = new Decision[mission.CommonPara.FishCntPerTeam];
            }

            Field field = Field.Instance();
            bool left = mission.TeamsRef[teamId].Para.MyHalfCourt == HalfCourt.LEFT;
            xna.Vector3 goal = new xna.Vector3(left ? field.RightMm : field.LeftMm, 0, 0);
            for (int i = 0; i < mission.TeamsRef[teamId].Fishes.Count; i++)
            {
                RoboFish fish = mission.TeamsRef[teamId].Fishes[i];
                xna.Vector3 ball = mission.EnvRef.Balls[0].PositionMm;
                float toGoal = xna.MathHelper.ToRadians(Helpers.GetAngleDegree(goal - ball));
                Helpers.Dribble(ref decisions[i], fish, ball, toGoal, 10, 30, 150, 14, 8, 15,
                    mission.CommonPara.MsPerCycle, false);
            }

            return decisions;
        }
    }
}
// </snippet>
