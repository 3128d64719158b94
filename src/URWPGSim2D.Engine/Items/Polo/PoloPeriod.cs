namespace URWPGSim2D.Engine.Items.Polo;

/// <summary>The phases of a water-polo match, numbered as the original's <c>CompetitionPeriod</c> (the strategies' variable).</summary>
internal enum PoloPeriod
{
    /// <summary>Normal time: the cycles asked for, two halves.</summary>
    NormalTime = 0,

    /// <summary>Extra time after a tie: 3 minutes, two halves.</summary>
    ExtraTime = 1,

    /// <summary>Penalties after a tie in extra time: kicks of 20 s, team 0 first, up to five rounds.</summary>
    PenaltyKickTime = 2,

    /// <summary>Clutch shot after tied penalties: 5 minutes, two halves, the first goal wins.</summary>
    ClutchShotTime = 3,
}
