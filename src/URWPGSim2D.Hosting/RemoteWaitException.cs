namespace URWPGSim2D.Hosting;

/// <summary>No client took a remote team's slot within <c>--remote-wait</c>; the message is one line for the command line.</summary>
public sealed class RemoteWaitException(string message) : StrategyLoadException(message);
