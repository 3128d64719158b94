// A test strategy in the original's style (written for this repository) that misbehaves on purpose:
// cycles 5..9 it throws, 10..14 it returns too few decisions, from cycle 20 it hangs. A test may
// set Hang to take over what hanging means (a deterministic clock); otherwise it sleeps forever.
using System;
using System.Threading;
using URWPGSim2D.Common;
using URWPGSim2D.StrategyLoader;

namespace URWPGSim2D.Strategy
{
    public class Strategy : MarshalByRefObject, IStrategy
    {
        public override object InitializeLifetimeService() { return null; }

        public static Action Hang;
        public int Calls;

        public string GetTeamName() { return "Faulty"; }

        public Decision[] GetDecision(Mission mission, int teamId)
        {
            Calls++;
            int cycle = Calls;
            if (cycle >= 5 && cycle <= 9) throw new InvalidOperationException("faulty on purpose");
            if (cycle >= 10 && cycle <= 14) return new Decision[0];
            if (cycle >= 20)
            {
                if (Hang != null) Hang(); else Thread.Sleep(Timeout.Infinite);
            }
            Decision[] d = new Decision[mission.CommonPara.FishCntPerTeam];
            for (int i = 0; i < d.Length; i++) { d[i].VCode = cycle < 10 ? 10 : 4; d[i].TCode = 7; }
            return d;
        }
    }
}
