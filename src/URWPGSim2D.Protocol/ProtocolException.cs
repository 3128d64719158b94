namespace URWPGSim2D.Protocol;

/// <summary>A message that breaks the protocol: not JSON, too long, a missing or mistyped field. The message is one line naming the field.</summary>
public sealed class ProtocolException : Exception
{
    /// <summary>Creates the exception.</summary>
    public ProtocolException(string message)
        : base(message)
    {
    }
}
