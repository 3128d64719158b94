using URWPGSim2D.Server.Hosting;

namespace URWPGSim2D.Server.Scenario;

/// <summary>A strategy that takes over a whole team (from <c>--strategy TEAM=path</c> or a test).</summary>
/// <param name="Label">What to call it in the summary.</param>
/// <param name="Strategy">The strategy instance.</param>
/// <param name="Isolated">Run it on its own thread with a time limit (loaded strategies always are).</param>
/// <param name="Clock">The deadline clock of an isolated strategy (null: its thread's CPU time; tests pass a <see cref="ManualStrategyClock"/>).</param>
internal sealed record TeamStrategy(string Label, IStrategy Strategy, bool Isolated, StrategyClock? Clock = null);
