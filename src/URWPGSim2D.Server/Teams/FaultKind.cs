namespace URWPGSim2D.Server.Teams;

/// <summary>What a strategy's fault in a cycle was (the fault table of docs/strategies.md).</summary>
internal enum FaultKind
{
    /// <summary>The strategy threw.</summary>
    Exception,

    /// <summary>It missed its deadline or was still busy.</summary>
    Timeout,

    /// <summary>It answered something unusable.</summary>
    BadAnswer,

    /// <summary>Its host ended, or the strategy could not be created: its fish stop for the rest of the match.</summary>
    Ended,

    /// <summary>Its remote client disconnected (or was cut off): its fish stop until a client connects again.</summary>
    Disconnected,
}
