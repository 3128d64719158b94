namespace URWPGSim2D.Protocol;

/// <summary>A client's first message.</summary>
/// <param name="Version">The protocol version the client speaks.</param>
/// <param name="Token">The token the server asked for, or null.</param>
/// <param name="Name">The strategy's team name, or null.</param>
public sealed record HelloMessage(int Version, string? Token, string? Name)
{
    /// <summary>Whether the client reads packed <c>cycle</c> messages (<see cref="PackedCycle"/>): it said <c>"packed":true</c>.</summary>
    public bool Packed { get; init; }

    /// <summary>
    /// Whether the client can play several matches on one connection: it said <c>"series":true</c>. After each
    /// <c>end</c> such a client says hello again and waits for the next <c>assignment</c> (or the connection's close).
    /// </summary>
    public bool Series { get; init; }
}
