namespace URWPGSim2D.Common;

/// <summary>The parameters every competition item shares.</summary>
[Serializable]
public class MissionCommonPara : ICloneable
{
    /// <summary>Creates empty parameters.</summary>
    public MissionCommonPara()
    {
    }

    /// <summary>Creates an item's parameters; <see cref="RemainingCycles"/> is the whole item.</summary>
    /// <param name="strName">Item name.</param>
    /// <param name="iTeamCount">Number of teams.</param>
    /// <param name="iFishCntPerTeam">Fish per team.</param>
    /// <param name="iTotalSeconds">Duration, s.</param>
    /// <param name="iMsPerCycle">Cycle length, ms.</param>
    /// <param name="isGoalBlockNeeded">Whether goal blocks are drawn.</param>
    /// <param name="isFieldInnerLinesNeeded">Whether the inner field lines are drawn.</param>
    public MissionCommonPara(string strName, int iTeamCount, int iFishCntPerTeam, int iTotalSeconds, int iMsPerCycle, bool isGoalBlockNeeded, bool isFieldInnerLinesNeeded)
        : this(strName, iTeamCount, iFishCntPerTeam, iTotalSeconds, iMsPerCycle, isGoalBlockNeeded, isFieldInnerLinesNeeded ? 1 : 0)
    {
    }

    /// <summary>Creates an item's parameters with a field-line style number.</summary>
    /// <param name="strName">Item name.</param>
    /// <param name="iTeamCount">Number of teams.</param>
    /// <param name="iFishCntPerTeam">Fish per team.</param>
    /// <param name="iTotalSeconds">Duration, s.</param>
    /// <param name="iMsPerCycle">Cycle length, ms.</param>
    /// <param name="isGoalBlockNeeded">Whether goal blocks are drawn.</param>
    /// <param name="isFieldInnerLinesNeeded">Which inner field lines are drawn (0 none).</param>
    public MissionCommonPara(string strName, int iTeamCount, int iFishCntPerTeam, int iTotalSeconds, int iMsPerCycle, bool isGoalBlockNeeded, int isFieldInnerLinesNeeded)
    {
        Name = strName;
        TeamCount = iTeamCount;
        FishCntPerTeam = iFishCntPerTeam;
        TotalSeconds = iTotalSeconds;
        MsPerCycle = iMsPerCycle;
        IsGoalBlockNeeded = isGoalBlockNeeded;
        IsFieldInnerLinesNeeded = isFieldInnerLinesNeeded;
        RemainingCycles = iMsPerCycle > 0 ? iTotalSeconds * 1000 / iMsPerCycle : 0;
    }

    /// <summary>The item's name (e.g. 抢球博弈).</summary>
    public string Name = string.Empty;

    /// <summary>Number of teams.</summary>
    public int TeamCount;

    /// <summary>Fish per team.</summary>
    public int FishCntPerTeam;

    /// <summary>Duration of the item, s.</summary>
    public int TotalSeconds;

    /// <summary>Length of a cycle, ms (100).</summary>
    public int MsPerCycle;

    /// <summary>Cycles left to play.</summary>
    public int RemainingCycles;

    /// <summary>Whether the match is running (true while strategies are called).</summary>
    public bool IsRunning;

    /// <summary>Whether the match is paused.</summary>
    public bool IsPaused;

    /// <summary>Whether the original would show a message box this cycle (never here).</summary>
    public bool IsShowDlgNeeded;

    /// <summary>The message the original would show.</summary>
    public string Message = string.Empty;

    /// <summary>Cycles the original's fish-info window has been open (0).</summary>
    public int DisplayingCycles;

    /// <summary>Whether the original would pause after this cycle (never here).</summary>
    public bool IsPauseNeeded;

    /// <summary>True after the half-time swap of sides.</summary>
    public bool IsExchangedHalfCourt;

    /// <summary>Whether the item draws goal blocks.</summary>
    public bool IsGoalBlockNeeded;

    /// <summary>Which inner field lines the item draws (0 none).</summary>
    public int IsFieldInnerLinesNeeded;

    /// <summary>A copy of the parameters.</summary>
    /// <returns>A new <see cref="MissionCommonPara"/>.</returns>
    public virtual object Clone() => MemberwiseClone();
}
