using System.Collections;

namespace URWPGSim2D.Common;

/// <summary>
/// What a strategy receives every cycle: the item's parameters, both teams with their fish, the
/// environment (field, balls, obstacles) and the item's variables. Each team gets its own deep copy
/// every cycle, so a strategy may change it freely.
/// </summary>
[Serializable]
public partial class Mission : ICloneable
{
    /// <summary>Creates the original's default mission parameters (1 versus 1, 10 minutes, 100 ms cycles).</summary>
    public Mission()
    {
        CommonPara.Name = "1 Versus 1";
        CommonPara.TeamCount = 2;
        CommonPara.FishCntPerTeam = 1;
        CommonPara.TotalSeconds = 600;
        CommonPara.MsPerCycle = 100;
        CommonPara.RemainingCycles = CommonPara.TotalSeconds * 1000 / CommonPara.MsPerCycle;
    }

    /// <summary>The item's parameters.</summary>
    public MissionCommonPara CommonPara = new();

    /// <summary>The teams; <c>TeamsRef[0]</c> is the team on the left half.</summary>
    public List<Team<RoboFish>> TeamsRef = new();

    /// <summary>Field, balls, obstacles and channels.</summary>
    public SimEnvironment EnvRef = new();

    /// <summary>The original's decision table [team, fish] (null in a strategy's copy).</summary>
    public Decision[,]? DecisionRef;

    /// <summary>The item's state: string keys and string values (read ints with <c>Convert.ToInt32</c>).</summary>
    public Hashtable HtMissionVariables = new();

    /// <summary>The item's parameters.</summary>
    /// <returns><see cref="CommonPara"/>.</returns>
    public MissionCommonPara GetMissionCommonPara() => CommonPara;

    /// <summary>The teams.</summary>
    /// <returns><see cref="TeamsRef"/>.</returns>
    public List<Team<RoboFish>> GetTeams() => TeamsRef;

    /// <summary>The environment.</summary>
    /// <returns><see cref="EnvRef"/>.</returns>
    public SimEnvironment GetEnvironment() => EnvRef;

    /// <summary>The decision table.</summary>
    /// <returns><see cref="DecisionRef"/>.</returns>
    public Decision[,]? GetDecision() => DecisionRef;

    /// <summary>The snapshot the host built this mission from (null for a mission made by hand): what <see cref="StrategyHelper.CollisionQueries"/> asks about.</summary>
    internal Strategies.MatchSnapshot? Source { get; set; }

    /// <summary>A deep copy (parameters, teams and fish, environment, variables).</summary>
    /// <returns>A new <see cref="Mission"/>.</returns>
    public virtual object Clone()
    {
        var copy = new Mission { CommonPara = (MissionCommonPara)CommonPara.Clone(), EnvRef = (SimEnvironment)EnvRef.Clone() };
        foreach (var team in TeamsRef)
        {
            var t = new Team<RoboFish> { Para = (TeamCommonPara)team.Para.Clone() };
            foreach (var fish in team.Fishes)
            {
                t.Fishes.Add((RoboFish)fish.Clone());
            }

            copy.TeamsRef.Add(t);
        }

        copy.HtMissionVariables = (Hashtable)HtMissionVariables.Clone();
        copy.Source = Source;
        return copy;
    }
}
