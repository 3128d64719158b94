namespace URWPGSim2D.Hosting;

/// <summary>The strategy's class was found but creating it failed: its constructor or static constructor threw.</summary>
public sealed class StrategyCreationException : StrategyLoadException
{
    /// <summary>Creates the exception with a one-line message.</summary>
    public StrategyCreationException(string message)
        : base(message)
    {
    }
}
