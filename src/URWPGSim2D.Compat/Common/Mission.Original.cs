using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>
/// The original's other public members of <see cref="Mission"/>. The members that ran the original's
/// simulation (its locomotion, collision and drawing steps) are not here: the server simulates. The
/// <c>Reset…</c>, <see cref="SetMission"/> and <see cref="ProcessControlRules"/> hooks are the original's
/// virtual no-ops for items to override; calling them on a strategy's copy changes only that copy
/// (and <see cref="ResetField"/> the process's <see cref="Field"/>, which the server sets again before every call).
/// </summary>
public partial class Mission
{
    /// <summary>Mirrors the pose of every fish of the teams on the right half (<see cref="RoboFish.ReversePose"/>): the original's step before drawing or passing a right-half team its view.</summary>
    public void ReversePose()
    {
        foreach (var team in TeamsRef)
        {
            if (team.Para.MyHalfCourt == HalfCourt.RIGHT)
            {
                foreach (var fish in team.Fishes)
                {
                    fish.ReversePose();
                }
            }
        }
    }

    /// <summary>Restores the poses <see cref="ReversePose"/> mirrored (<see cref="RoboFish.RecoveryPose"/>).</summary>
    public void RecoveryPose()
    {
        foreach (var team in TeamsRef)
        {
            if (team.Para.MyHalfCourt == HalfCourt.RIGHT)
            {
                foreach (var fish in team.Fishes)
                {
                    fish.RecoveryPose();
                }
            }
        }
    }

    /// <summary>Copies the values of <paramref name="para"/> into <see cref="CommonPara"/> (the object stays the same, as in the original).</summary>
    /// <param name="para">The parameters to copy.</param>
    public void SetMissionCommonPara(MissionCommonPara para)
    {
        System.ArgumentNullException.ThrowIfNull(para);
        var to = CommonPara;
        to.FishCntPerTeam = para.FishCntPerTeam;
        to.IsRunning = para.IsRunning;
        to.MsPerCycle = para.MsPerCycle;
        to.Name = para.Name;
        to.RemainingCycles = para.RemainingCycles;
        to.TeamCount = para.TeamCount;
        to.TotalSeconds = para.TotalSeconds;
        to.IsExchangedHalfCourt = para.IsExchangedHalfCourt;
        to.DisplayingCycles = para.DisplayingCycles;
        to.IsPaused = para.IsPaused;
        to.IsGoalBlockNeeded = para.IsGoalBlockNeeded;
        to.IsFieldInnerLinesNeeded = para.IsFieldInnerLinesNeeded;
    }

    /// <summary>The original's hook that sets up an item's objects; does nothing here (items are the server's).</summary>
    public virtual void SetMission()
    {
    }

    /// <summary>The original's hook for an item's rules each cycle; does nothing here (the server applies the rules).</summary>
    public virtual void ProcessControlRules()
    {
    }

    /// <summary>The original's hook to reset teams and fish; does nothing here.</summary>
    public virtual void ResetTeamsAndFishes()
    {
    }

    /// <summary>The original's hook to reset an item's goal handling; does nothing here.</summary>
    public virtual void ResetGoalHandler()
    {
    }

    /// <summary>The original's hook to reset a shoot-out; does nothing here.</summary>
    public virtual void ResetShootout()
    {
    }

    /// <summary>The original's hook to put the balls back; does nothing here.</summary>
    public virtual void ResetBalls()
    {
    }

    /// <summary>The original's hook to put the obstacles back; does nothing here.</summary>
    public virtual void ResetObstacles()
    {
    }

    /// <summary>The original's hook to put the moving obstacles back; does nothing here.</summary>
    public virtual void ResetDynamicObstacles()
    {
    }

    /// <summary>The original's hook to recolour the fish; does nothing here.</summary>
    public virtual void ResetColorFishAndId()
    {
    }

    /// <summary>The original's hook to reset the environment; does nothing here.</summary>
    public virtual void ResetEnvironment()
    {
    }

    /// <summary>Colours every ball pink (fill and border), the original's default (display only).</summary>
    public virtual void ResetColorBall()
    {
        foreach (var ball in EnvRef.Balls)
        {
            ball.ColorFilled = Color.Pink;
            ball.ColorBorder = Color.Pink;
        }
    }

    /// <summary>Sets the field's lengths back to their configured values (<see cref="Field.FieldLengthXOriMm"/>, <see cref="Field.FieldLengthZOriMm"/>) and recomputes the rest (<see cref="Field.FieldCalculation"/>).</summary>
    public virtual void ResetField()
    {
        var f = Field.Instance();
        f.FieldLengthXMm = f.FieldLengthXOriMm;
        f.FieldLengthZMm = f.FieldLengthZOriMm;
        f.FieldCalculation();
    }

    /// <summary>Sets a fish's body colour (display only); ignored outside the item's team and fish counts, as in the original.</summary>
    /// <param name="teamId">Team index.</param>
    /// <param name="fishId">Fish index in the team.</param>
    /// <param name="colorFish">The colour.</param>
    public void SetColorFish(int teamId, int fishId, Color colorFish)
    {
        if (Has(teamId, fishId))
        {
            TeamsRef[teamId].Fishes[fishId].ColorFish = colorFish;
        }
    }

    /// <summary>Sets a fish's position and body direction in this mission object; ignored outside the item's team and fish counts, as in the original. A strategy's copy is its own: the server's fish do not move.</summary>
    /// <param name="teamId">Team index.</param>
    /// <param name="fishId">Fish index in the team.</param>
    /// <param name="position">The position, mm.</param>
    /// <param name="direction">The body direction, rad.</param>
    public void SetFishPose(int teamId, int fishId, Xna.Vector3 position, float direction)
    {
        if (Has(teamId, fishId))
        {
            var fish = TeamsRef[teamId].Fishes[fishId];
            fish.PositionMm = position;
            fish.BodyDirectionRad = direction;
        }
    }

    private bool Has(int teamId, int fishId) =>
        teamId >= 0 && teamId < CommonPara.TeamCount && fishId >= 0 && fishId < CommonPara.FishCntPerTeam
        && teamId < TeamsRef.Count && fishId < TeamsRef[teamId].Fishes.Count;
}
