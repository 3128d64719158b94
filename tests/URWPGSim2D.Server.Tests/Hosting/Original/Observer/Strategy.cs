// A test strategy in the original's style (written for this repository): it reads the item's
// variables, the obstacles and the head tips, and keeps what it saw in public fields for the test.
using System;
using System.Collections;
using xna = Microsoft.Xna.Framework;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;
using URWPGSim2D.Core;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        public override object InitializeLifetimeService() { return null; }

        public int Calls;
        public int LastTeamId = -1;
        public int VariableCount;
        public string VariableText = "";
        public int RectCount, RoundCount;
        public float FirstRectX, FirstRectZ, FirstRoundRadius;
        public float HeadAhead = -1;
        public float MaxHeadError;
        public int RemainingCycles;
        public string ItemName = "";
        public bool Exchanged;
        public HalfCourt MyHalf;
        public float TableV14;

        public string GetTeamName() { return "Observer"; }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            Calls++;
            LastTeamId = teamId;
            VariableCount = mission.HtMissionVariables.Count;
            string text = "";
            foreach (DictionaryEntry e in mission.HtMissionVariables)
            {
                if ((string)e.Key == "Ball_0_Left_Status") text += "left=" + Convert.ToInt32(e.Value) + ";";
            }
            if (mission.HtMissionVariables.ContainsKey("Ball_0_Right_Status"))
            {
                text += "right=" + Convert.ToInt32(mission.HtMissionVariables["Ball_0_Right_Status"]) + ";";
            }
            VariableText = text;
            RectCount = mission.EnvRef.ObstaclesRect.Count;
            RoundCount = mission.EnvRef.ObstaclesRound.Count;
            if (RectCount > 0) { FirstRectX = mission.EnvRef.ObstaclesRect[0].PositionMm.X; FirstRectZ = mission.EnvRef.ObstaclesRect[0].PositionMm.Z; }
            if (RoundCount > 0) { FirstRoundRadius = mission.EnvRef.ObstaclesRound[0].RadiusMm; }
            foreach (Team<RoboFish> team in mission.TeamsRef)
            {
                foreach (RoboFish f in team.Fishes)
                {
                    xna.Vector3 ahead = f.PolygonVertices[0] - f.PositionMm;
                    HeadAhead = ahead.Length();
                    float dir = (float)Math.Atan2(ahead.Z, ahead.X);
                    float err = Math.Abs(xna.MathHelper.WrapAngle(dir - f.BodyDirectionRad));
                    if (err > MaxHeadError) MaxHeadError = err;
                }
            }
            RemainingCycles = mission.CommonPara.RemainingCycles;
            ItemName = mission.CommonPara.Name;
            Exchanged = mission.CommonPara.IsExchangedHalfCourt;
            MyHalf = mission.TeamsRef[teamId].Para.MyHalfCourt;
            TableV14 = DataBasedOnExperiment.VCodeAndVelocityTable[14];

            Decision[] d = new Decision[mission.CommonPara.FishCntPerTeam];
            for (int i = 0; i < d.Length; i++) { d[i].VCode = 5 + teamId; d[i].TCode = 7; }
            return d;
        }
    }
}
