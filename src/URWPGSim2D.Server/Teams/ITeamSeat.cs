namespace URWPGSim2D.Server.Teams;

/// <summary>
/// One strategy's place in a match as the match's record sees it: the team it plays for, its name,
/// its latest fault, and what it drew and printed in the cycle just decided.
/// </summary>
internal interface ITeamSeat
{
    /// <summary>The team the strategy plays for.</summary>
    int Team { get; }

    /// <summary>The strategy's name as shown to people: the team's own name, else its spec.</summary>
    string Label { get; }

    /// <summary>The cycle of the latest fault, or 0.</summary>
    int LastFaultCycle { get; }

    /// <summary>What the latest fault was, or null.</summary>
    string? LastFault { get; }

    /// <summary>The kind of the latest fault.</summary>
    FaultKind LastFaultKind { get; }

    /// <summary>The strategy's debug drawings of the cycle just decided, or null when drawings are not recorded.</summary>
    DebugRecorder? Drawings { get; }

    /// <summary>What the strategy printed in the cycle just decided, or null when its output is not recorded.</summary>
    StrategyLog? Log { get; }
}
