namespace URWPGSim2D.Tests.OldStrategies;

/// <summary>
/// Team strategies written for these tests in the style of the original's entries (C# 3, the
/// original's template: <c>URWPGSim2D.Strategy.Strategy : MarshalByRefObject, IStrategy</c>), compiled
/// into old-style DLLs by <see cref="OldStrategyCompiler"/>.
/// </summary>
internal static class OldStrategySources
{
    /// <summary>Every fish of the team pushes the nearest ball toward the other side's goal with
    /// <c>Helpers.Dribble</c>; counts its calls in <c>Calls</c>.</summary>
    public const string Dribbler = """
        using System;
        using System.Collections.Generic;
        using xna = Microsoft.Xna.Framework;
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
                    return "Old dribbler";
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
                            decisions[i].VCode = 4;
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
        """;

    /// <summary>Swims straight on for a while, then throws from <c>GetDecision</c> on every call.</summary>
    public const string Faulty = """
        using System;
        using URWPGSim2D.Common;
        using URWPGSim2D.StrategyLoader;

        namespace URWPGSim2D.Strategy
        {
            public class Strategy : MarshalByRefObject, IStrategy
            {
                private int calls;

                public string GetTeamName() { return "Old faulty"; }

                public Decision[] GetDecision(Mission mission, int teamId)
                {
                    calls++;
                    if (calls > 10) throw new InvalidOperationException("broken after ten cycles");
                    Decision[] decisions = new Decision[mission.CommonPara.FishCntPerTeam];
                    for (int i = 0; i < decisions.Length; i++) { decisions[i].VCode = 14; decisions[i].TCode = 7; }
                    return decisions;
                }
            }
        }
        """;

    /// <summary>A strategy whose <c>Touch</c> refers to every member of the original's API
    /// (<see cref="ApiToucher"/>); it swims straight on.</summary>
    public const string Toucher = """
        using System;
        using URWPGSim2D.Common;
        using URWPGSim2D.StrategyLoader;

        namespace URWPGSim2D.Strategy
        {
            public class Strategy : MarshalByRefObject, IStrategy
            {
                public string GetTeamName() { return "Old toucher " + OldApi.Toucher.Touch(false); }

                public Decision[] GetDecision(Mission mission, int teamId)
                {
                    return new Decision[mission.CommonPara.FishCntPerTeam];
                }
            }
        }
        """;

    /// <summary>
    /// Reads the older items' <c>HtMissionVariables</c> as their entries did (<c>Convert.ToInt32</c>,
    /// <c>Convert.ToBoolean</c> on the <c>Hashtable</c>'s values) and writes what it read, key=value in
    /// the original's key order, to <c>Seen</c>; its fish swim slowly straight on.
    /// </summary>
    public const string VariableReader = """
        using System;
        using URWPGSim2D.Common;
        using URWPGSim2D.StrategyLoader;

        namespace URWPGSim2D.Strategy
        {
            public class Strategy : MarshalByRefObject, IStrategy
            {
                public string Seen = "";

                private static readonly string[] Numbers = new string[] { "CompetitionPeriod", "ExecutingTaskNo", "FinishedSingleTripCount" };

                public string GetTeamName() { return "Old variable reader"; }

                public Decision[] GetDecision(Mission mission, int teamId)
                {
                    string seen = "";
                    for (int stage = 1; stage <= 4; stage++)
                    {
                        for (int fish = 0; fish < 2; fish++)
                        {
                            string key = "IsCollidedBallAndFish" + Convert.ToString(fish);
                            key = key + "AtStage" + Convert.ToString(stage);
                            if (mission.HtMissionVariables.ContainsKey(key))
                            {
                                bool touched = Convert.ToBoolean(mission.HtMissionVariables[key]);
                                seen = seen + key + "=";
                                seen = seen + (touched ? "yes" : "no") + ";";
                            }
                        }
                    }
                    foreach (string key in Numbers)
                    {
                        if (mission.HtMissionVariables.ContainsKey(key))
                        {
                            int value = Convert.ToInt32(mission.HtMissionVariables[key]);
                            seen = seen + key + "=";
                            seen = seen + Convert.ToString(value) + ";";
                        }
                    }
                    Seen = seen;
                    Decision[] decisions = new Decision[mission.CommonPara.FishCntPerTeam];
                    for (int i = 0; i < decisions.Length; i++) { decisions[i].VCode = 2; decisions[i].TCode = 7; }
                    return decisions;
                }
            }
        }
        """;
}
