// A test strategy of the original API (written for this repository) that draws with the new
// StrategyHelper.DebugDraw: a gold circle around each of its fish, a line from each fish to ball 0
// and the team's text at ball 0. Its decisions are constant.
using System;
using System.Drawing;
using xna = Microsoft.Xna.Framework;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;
using URWPGSim2D.StrategyHelper;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        public string GetTeamName()
        {
            return "Drawer";
        }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            var fishes = mission.TeamsRef[teamId].Fishes;
            var decisions = new Decision[fishes.Count];
            for (int i = 0; i < fishes.Count; i++)
            {
                decisions[i].VCode = 6;
                decisions[i].TCode = 5;
                DebugDraw.Circle(fishes[i].PositionMm, 50f, i, Color.Gold);
                if (mission.EnvRef.Balls.Count > 0)
                {
                    DebugDraw.Line(fishes[i].PositionMm, mission.EnvRef.Balls[0].PositionMm, i);
                }
            }

            if (mission.EnvRef.Balls.Count > 0 && DebugDraw.IsOn)
            {
                DebugDraw.Text(mission.EnvRef.Balls[0].PositionMm, "ball 0");
            }

            return decisions;
        }
    }
}
