using System;
using URWPGSim2D.Protocol;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// A team's strategy in a strategy host process: starts the host (<see cref="HostProcess"/>) and
/// plays it over a <see cref="StrategyConnection"/>, the code path a remote client's connection
/// takes too. The host answers every call when it returns; the server measures the call (wall time,
/// and the CPU time of the host's whole sandbox where a control group counts it) against the team's
/// time bank, and the watchdog kills a host that does not answer within the time the server waits.
/// A host that ends is not restarted (the next match starts a new one).
/// </summary>
internal static class HostedStrategy
{
    /// <summary>Wall time a host has from its start to its hello (the .NET runtime starts, the strategy is loaded and created).</summary>
    public static readonly TimeSpan StartLimit = TimeSpan.FromSeconds(30);

    /// <summary>Wall time the server waits for a host's answer before it kills the host: twice the hang limit of the deadline and 5 s.</summary>
    public static TimeSpan AnswerLimit(int deadlineMs) => ThreadTimeClock.HangLimitFor(TimeSpan.FromMilliseconds(deadlineMs)) * 2 + TimeSpan.FromSeconds(5);

    /// <summary>Starts the host of <paramref name="strategy"/> for the team and match of <paramref name="assignment"/>.</summary>
    public static StrategyConnection Start(PreparedStrategy strategy, HostSettings settings, AssignmentMessage assignment, int cycles)
    {
        ArgumentNullException.ThrowIfNull(strategy);
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentNullException.ThrowIfNull(assignment);

        // CPU time of the whole host: every cycle at its deadline, and a minute for the start.
        long cpu = 60 + ((long)Math.Max(cycles, 1) * assignment.DeadlineMs / 1000 * 2);
        var process = HostProcess.Start(strategy.LoadSpec, strategy.ReadOnly, HostSandbox.Use(settings.Sandbox), settings, (int)Math.Min(cpu, int.MaxValue));
        return new StrategyConnection(process, assignment, AnswerLimit(assignment.DeadlineMs), StartLimit, token: null, log: null, peer: "the host");
    }
}
