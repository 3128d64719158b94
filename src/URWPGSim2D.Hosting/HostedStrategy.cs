using URWPGSim2D.Protocol;

namespace URWPGSim2D.Hosting;

/// <summary>
/// A team's strategy in a strategy host process: starts the host (<see cref="HostProcess"/>) and
/// plays it over a <see cref="StrategyConnection"/>, the code path a remote client's connection
/// takes too. The host answers every call when it returns; the server measures the call (wall time,
/// and the CPU time of the host's whole sandbox where a control group counts it) against the team's
/// time bank, and the watchdog kills a host that does not answer within the time the server waits.
/// A host that ends is not restarted (the next match starts a new one). A strategy goes to a
/// pre-started host when one waits for it (<see cref="HostPool"/>).
/// </summary>
internal static class HostedStrategy
{
    /// <summary>Wall time a host has from its start to its hello (the .NET runtime starts, the strategy is loaded and created).</summary>
    public static readonly TimeSpan StartLimit = TimeSpan.FromSeconds(30);

    /// <summary>Wall time the server waits for a host's answer before it kills the host: twice the hang limit of the deadline and 5 s.</summary>
    public static TimeSpan AnswerLimit(int deadlineMs) => ThreadTimeClock.HangLimitFor(TimeSpan.FromMilliseconds(deadlineMs)) * 2 + TimeSpan.FromSeconds(5);

    /// <summary>Starts the host of <paramref name="strategy"/> for the team and match of <paramref name="assignment"/> (a waiting one of <see cref="HostPool"/> when <paramref name="pooled"/> and one waits for it).</summary>
    public static StrategyConnection Start(PreparedStrategy strategy, HostSettings settings, AssignmentMessage assignment, int cycles, bool pooled = true)
    {
        ArgumentNullException.ThrowIfNull(strategy);
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentNullException.ThrowIfNull(assignment);

        int cpuSeconds = CpuSeconds(assignment, cycles);
        bool sandbox = HostSandbox.Use(settings.Sandbox);
        HostProcess? process = null;
        if (pooled && HostPool.Take(strategy, settings, sandbox) is { } waiting)
        {
            if (waiting.HandOver(strategy.LoadSpec, cpuSeconds))
            {
                process = waiting; // pre-started: its runtime is up already
            }
            else
            {
                waiting.Dispose();
            }
        }

        process ??= HostProcess.Start(strategy.LoadSpec, strategy.ReadOnly, sandbox, settings, cpuSeconds);
        return Connect(process, assignment);
    }

    /// <summary>Hands <paramref name="strategy"/> to the waiting host <paramref name="waiting"/> (<see cref="HostProcess.StartWaiting"/> with its files) and connects to it.</summary>
    /// <exception cref="InvalidOperationException">The host has gone.</exception>
    public static StrategyConnection HandOver(HostProcess waiting, PreparedStrategy strategy, AssignmentMessage assignment, int cycles)
    {
        ArgumentNullException.ThrowIfNull(waiting);
        ArgumentNullException.ThrowIfNull(strategy);
        ArgumentNullException.ThrowIfNull(assignment);
        if (!waiting.HandOver(strategy.LoadSpec, CpuSeconds(assignment, cycles)))
        {
            throw new InvalidOperationException("the strategy cannot be handed to the waiting host");
        }

        return Connect(waiting, assignment);
    }

    // CPU time of the whole host: every cycle at its deadline, and a minute for the start.
    private static int CpuSeconds(AssignmentMessage assignment, int cycles) =>
        (int)Math.Min(60 + ((long)Math.Max(cycles, 1) * assignment.DeadlineMs / 1000 * 2), int.MaxValue);

    private static StrategyConnection Connect(HostProcess process, AssignmentMessage assignment) =>
        new(process, assignment, AnswerLimit(assignment.DeadlineMs), StartLimit, token: null, log: null, peer: "the host");
}
