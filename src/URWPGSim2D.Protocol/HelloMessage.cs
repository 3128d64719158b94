namespace URWPGSim2D.Protocol;

/// <summary>A client's first message.</summary>
/// <param name="Version">The protocol version the client speaks.</param>
/// <param name="Token">The token the server asked for, or null.</param>
/// <param name="Name">The strategy's team name, or null.</param>
public sealed record HelloMessage(int Version, string? Token, string? Name)
{
    /// <summary>Whether the client reads packed <c>cycle</c> messages (<see cref="PackedCycle"/>): it said <c>"packed":true</c>.</summary>
    public bool Packed { get; init; }
}
