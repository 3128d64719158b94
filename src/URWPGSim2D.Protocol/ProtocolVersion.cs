namespace URWPGSim2D.Protocol;

/// <summary>The protocol's version numbers (docs/protocol.md, "Versions").</summary>
public static class ProtocolVersion
{
    /// <summary>The version this build speaks, sent in <c>hello</c> and <c>assignment</c>.</summary>
    public const int Current = 1;
}
