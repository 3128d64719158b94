namespace URWPGSim2D.Protocol;

/// <summary>The <c>type</c> of a protocol message (docs/protocol.md).</summary>
public enum MessageType
{
    /// <summary>A <c>type</c> this version does not know (or none).</summary>
    Unknown,

    /// <summary>Client → server, first: protocol version, token, team name.</summary>
    Hello,

    /// <summary>Server → client, after a hello: team, item, fish, field, obstacles, deadline.</summary>
    Assignment,

    /// <summary>Server → client, every cycle: what the strategy sees.</summary>
    Cycle,

    /// <summary>Client → server, every cycle: the cycle's decisions, or the fault that stopped them.</summary>
    Decisions,

    /// <summary>Server → client, last: the match is over, with its result.</summary>
    End,

    /// <summary>Server → client: the connection is refused (bad hello), then closed.</summary>
    Error,
}
