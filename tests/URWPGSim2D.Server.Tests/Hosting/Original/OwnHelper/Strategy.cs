// A test strategy in the original's style (written for this repository) using its own StrategyHelper.cs.
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

        private Decision[] decisions;

        public string GetTeamName() { return "OwnHelper"; }

        public int HelperUses { get { return Helpers.Uses; } }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            if (decisions == null) decisions = new Decision[mission.CommonPara.FishCntPerTeam];
            for (int i = 0; i < decisions.Length; i++)
            {
                Helpers.Dribble(ref decisions[i], mission.TeamsRef[teamId].Fishes[i], new xna.Vector3(0, 0, 5000));
            }
            return decisions;
        }
    }
}
