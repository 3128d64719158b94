namespace URWPGSim2D.Protocol;

/// <summary>Sizes a side of the protocol accepts (docs/protocol.md, "Limits").</summary>
public static class ProtocolLimits
{
    /// <summary>Longest line the server reads from a client, bytes (without the newline).</summary>
    public const int ClientLineBytes = 64 * 1024;

    /// <summary>Longest line a client reads from the server, bytes (a snapshot of about 250 bytes a fish).</summary>
    public const int ServerLineBytes = 64 * 1024 * 1024;

    /// <summary>Longest text field (token, name, fault message) a reader keeps, characters; longer ones are cut.</summary>
    public const int TextChars = 1024;

    /// <summary>Characters of a <c>decisions</c> message's <c>log</c> a reader keeps (what a strategy printed in one cycle).</summary>
    public const int LogChars = 4096;
}
