// A test strategy in the original's style (written for this repository) that vandalises the mission
// it receives; a fresh copy every cycle means none of it is seen again.
using System;
using xna = Microsoft.Xna.Framework;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        public override object InitializeLifetimeService() { return null; }

        public int Calls;
        public int Leaks;
        private Mission last;
        private RoboFish lastFish;

        public string GetTeamName() { return "Mutator"; }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            Calls++;
            if (mission.CommonPara.MsPerCycle != 100) Leaks++;
            if (mission.HtMissionVariables.ContainsKey("vandal")) Leaks++;
            if (ReferenceEquals(mission, last)) Leaks++;
            RoboFish me = mission.TeamsRef[teamId].Fishes[0];
            if (ReferenceEquals(me, lastFish)) Leaks++;
            if (me.PositionMm.Y != 0) Leaks++;
            if (mission.EnvRef.Balls.Count == 0 && Calls > 1) Leaks++;

            mission.CommonPara.MsPerCycle = 1;
            mission.HtMissionVariables["vandal"] = "1";
            me.PositionMm.Y = 999;
            me.PositionMm.X += 500;
            me.PolygonVertices[0] = new xna.Vector3(1, 2, 3);
            mission.EnvRef.Balls.Clear();
            mission.TeamsRef.Reverse();
            last = mission;
            lastFish = me;

            Decision[] d = new Decision[mission.TeamsRef[0].Fishes.Count + 5];
            for (int i = 0; i < d.Length; i++) { d[i].VCode = 40; d[i].TCode = -3; }
            return d;
        }
    }
}
