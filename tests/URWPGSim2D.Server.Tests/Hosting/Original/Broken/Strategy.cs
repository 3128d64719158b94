// A test strategy with compile errors on purpose (written for this repository).
using System;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        public string GetTeamName() { return "Broken"; }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            int x = undefinedThing;
            return mission.NoSuchMember;
        }
    }
}
