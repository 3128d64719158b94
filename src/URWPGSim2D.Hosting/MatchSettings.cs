using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Hosting;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Everything that decides a match before it is played: the scene (a competition item's layout, the
/// default scene, a crowd or a scenario file), how long it lasts, its seed and noise, the team
/// strategies and the motion world's threads. The same settings always play the same match
/// (<see cref="MatchLoop"/>), whatever command plays it.
/// </summary>
/// <param name="Scenario">The scene.</param>
/// <param name="Cycles">Cycles of regular time (600 a minute); an item that decides a tie plays on after them up to its referee's most.</param>
/// <param name="Seed">The seed of the noise and of the item's layout, or null for the scenario's.</param>
/// <param name="Noise">Whether the motion and observation noise is on, or null for the scenario's.</param>
/// <param name="Teams">Per team (index 0, 1): a strategy that takes every fish of the team, or null for the scenario's own (an item's demo).</param>
/// <param name="StrategyTimeoutMs">The deadline of an isolated strategy's call, ms of its thread's CPU time.</param>
/// <param name="Threads">Threads the motion world spreads a cycle's independent islands over (the same match whatever the count).</param>
/// <param name="DebugDraw">Whether the strategies' debug drawings are recorded in the trace (<c>run --debug-draw</c>).</param>
/// <param name="StrategyLog">Whether what the strategies print is recorded in the trace (<c>run --strategy-log</c>).</param>
/// <param name="TimeBank">Each team's time bank for late calls (<see cref="Hosting.TimeBank"/>), or null for the default (<see cref="Hosting.TimeBank.DefaultFor"/>).</param>
public sealed record MatchSettings(
    ScenarioDefinition Scenario,
    int Cycles,
    ulong? Seed = null,
    bool? Noise = null,
    TeamStrategy?[]? Teams = null,
    int StrategyTimeoutMs = MatchBuilder.DefaultStrategyTimeoutMs,
    int Threads = 1,
    bool DebugDraw = false,
    bool StrategyLog = false,
    System.TimeSpan? TimeBank = null)
{
    /// <summary>Builds a fresh match of these settings, ready for cycle 1.</summary>
    public Match Build()
    {
        var match = MatchBuilder.BuildRecording(Scenario, Teams, Seed, Noise, StrategyTimeoutMs, cycles: Cycles, debugDraw: DebugDraw, strategyLog: StrategyLog, timeBank: TimeBank);
        match.Motion.Threads = Threads;
        return match;
    }
}
