namespace URWPGSim2D.Common;

/// <summary>What the original tells a strategy about a team.</summary>
[Serializable]
public class TeamCommonPara : ICloneable
{
    /// <summary>Number of fish in the team.</summary>
    public int FishCount;

    /// <summary>The half the team defends; strategies branch on it (positions are never mirrored).</summary>
    public HalfCourt MyHalfCourt;

    /// <summary>The team's score (−1 when the item hides it).</summary>
    public int Score;

    /// <summary>The team's name.</summary>
    public string Name = string.Empty;

    /// <summary>Whether the team pressed Ready (always true while a match runs here).</summary>
    public bool IsReady;

    /// <summary>A copy of the team's parameters.</summary>
    /// <returns>A new <see cref="TeamCommonPara"/>.</returns>
    public virtual object Clone() => new TeamCommonPara { FishCount = FishCount, MyHalfCourt = MyHalfCourt, Score = Score, Name = Name, IsReady = IsReady };
}
