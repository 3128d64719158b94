namespace URWPGSim2D.Strategies;

/// <summary>
/// A strategy answered, but not with something the server can use (for example the wrong number of
/// decisions). The server counts it as a fault of its own kind and keeps the fish on their last decisions.
/// </summary>
public sealed class StrategyContractException : Exception
{
    /// <summary>Creates the exception.</summary>
    public StrategyContractException()
        : base("the strategy broke its contract")
    {
    }

    /// <summary>Creates the exception with a one-line message.</summary>
    /// <param name="message">What was wrong with the answer.</param>
    public StrategyContractException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    /// <param name="message">What was wrong with the answer.</param>
    /// <param name="innerException">The cause.</param>
    public StrategyContractException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}
