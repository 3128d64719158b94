// A team's own modified copy of the helper file (written for this repository): same namespace and
// class as the one the server ships, a different Dribble. The team's copy must win.
using System;
using xna = Microsoft.Xna.Framework;
using URWPGSim2D.Common;

namespace URWPGSim2D.StrategyHelper
{
    public static class Helpers
    {
        public static int Uses;

        // Not the server's signature: this only compiles against the team's own copy.
        public static void Dribble(ref Decision decision, RoboFish fish, xna.Vector3 destPtMm)
        {
            Uses++;
            decision.VCode = 3;
            decision.TCode = destPtMm.Z > fish.PositionMm.Z ? 11 : 3;
        }
    }
}
