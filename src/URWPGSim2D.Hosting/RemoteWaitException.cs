namespace URWPGSim2D.Hosting;

/// <summary>No client took a remote team's slot within <c>--remote-wait</c>; the message is one line for the command line.</summary>
/// <param name="message">The line.</param>
/// <param name="team">The team of the match whose client did not come.</param>
public sealed class RemoteWaitException(string message, int team = 0) : StrategyLoadException(message)
{
    /// <summary>The team of the match whose client did not come.</summary>
    public int Team { get; } = team;
}
