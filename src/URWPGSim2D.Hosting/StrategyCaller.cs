using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Asks every strategy slot, in a fixed order, for its fish's decisions. A strategy that throws or
/// answers with something unusable (<see cref="StrategyContractException"/>) leaves its fish on their
/// last decisions; the fault is counted for the summary and the results file, and the match goes on.
/// A strategy that runs isolated or in another process is waited for, however late, and pays for a
/// late call from its time bank (<see cref="TimeBank"/>): which answers count never depends on how
/// fast the server plays. A team whose bank is spent, or whose call is given up on, plays idle.
/// </summary>
public sealed class StrategyCaller : IMatchTeams
{
    /// <summary>Asks <paramref name="slots"/>; each isolated or hosted one gets a time bank of <paramref name="timeBank"/> for calls of <paramref name="timeoutMs"/>.</summary>
    /// <param name="slots">The slots, in decision order.</param>
    /// <param name="timeoutMs">The deadline of one call, ms of CPU time.</param>
    /// <param name="timeBank">Each team's bank for the match, or null for the least default bank (<see cref="Hosting.TimeBank.DefaultFor"/>).</param>
    public StrategyCaller(StrategySlot[] slots, int timeoutMs, TimeSpan? timeBank = null)
    {
        Slots = slots;
        TimeoutMs = timeoutMs;
        TimeBank = timeBank ?? Hosting.TimeBank.DefaultFor(0, timeoutMs);
        foreach (var slot in slots)
        {
            if (slot.Runner is not null || slot.Hosted is not null)
            {
                slot.Bank = new TimeBank(TimeSpan.FromMilliseconds(timeoutMs), TimeBank);
            }
        }
    }

    /// <summary>The slots, in decision order.</summary>
    public StrategySlot[] Slots { get; }

    /// <inheritdoc/>
    IReadOnlyList<TeamSeat> IMatchTeams.Seats => Slots;

    /// <summary>The deadline of a call of an isolated or hosted strategy, ms of CPU time.</summary>
    public int TimeoutMs { get; }

    /// <summary>Each team's time bank at the start of the match.</summary>
    public TimeSpan TimeBank { get; }

    /// <summary>
    /// Connects the match's remote teams before it starts: first every remote team's address is
    /// announced (a second team's client must know its port before the first client connects),
    /// then each team's client is waited for. A match without remote teams returns at once.
    /// </summary>
    /// <exception cref="RemoteWaitException">A remote team's client did not connect or was refused.</exception>
    public void ConnectRemoteTeams()
    {
        foreach (var slot in Slots)
        {
            (slot.Hosted as RemoteStrategy)?.Announce();
        }

        foreach (var slot in Slots)
        {
            (slot.Hosted as RemoteStrategy)?.WaitForClient(announced: true);
        }
    }

    /// <summary>Total faults of all slots.</summary>
    public int TotalFaults
    {
        get
        {
            int n = 0;
            foreach (var s in Slots)
            {
                n += s.Faults;
            }

            return n;
        }
    }

    /// <summary>Ends the threads of the isolated strategies and the strategy hosts (after the match), telling hosts the result.</summary>
    /// <param name="cycles">Cycles played.</param>
    /// <param name="goals">Each team's final score (the item's, else the goals).</param>
    public void Stop(int cycles, IReadOnlyList<int> goals)
    {
        var end = new int[Math.Max(2, goals.Count)];
        for (int t = 0; t < goals.Count; t++)
        {
            end[t] = goals[t];
        }

        // Every slot is stopped, whatever one of them throws; the first failure is then put on its team.
        TeamFaultException? failure = null;
        foreach (var slot in Slots)
        {
            try
            {
                slot.Runner?.Stop();
                if (slot.IdleFromCycle == 0 || slot.Hosted is RemoteStrategy { Series: true })
                {
                    slot.Hosted?.Stop(new Protocol.EndMessage(cycles, end, slot.Faults));
                }
                else
                {
                    slot.Hosted?.Dispose(); // out of time: nothing more is said to it (a remote client that plays a series is told the end above, for its next match)
                }
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                failure ??= new TeamFaultException(slot.Team, e);
            }
        }

        if (failure is not null)
        {
            throw failure;
        }
    }

    /// <summary>Ends the threads of the isolated strategies and the strategy hosts of a match never played (cycle 0, no goals).</summary>
    public void Stop() => Stop(0, [0, 0]);

    /// <summary>Runs every strategy on <paramref name="snapshot"/> and writes the fish's decisions.</summary>
    public void Decide(MatchSnapshot snapshot, FishState[] fish)
    {
        int cycle = snapshot.Cycle + 1; // the cycle these decisions drive
        foreach (var slot in Slots)
        {
            slot.Decisions.CopyTo(slot.Scratch, 0);
            slot.Drawings?.Reset(slot.Fish);
            slot.Log?.Clear();
            if (slot.EndedInCycle > 0 || slot.IdleFromCycle > 0)
            {
                // its host has ended (or it was never created), or its time is spent: its fish stay stopped
            }
            else if (slot.CreationFault is { } why)
            {
                slot.Charge(cycle, FaultKind.Ended, why);
            }
            else if (slot.Hosted is { } hosted)
            {
                Hosted(slot, hosted, snapshot, cycle);
            }
            else if (slot.Runner is null)
            {
                slot.Drawings?.Enter(slot.Fish);
                if (slot.Log is { } log)
                {
                    ConsoleRouter.Enter(log);
                }

                try
                {
                    slot.DecideInProcess(slot.Strategy!, snapshot, cycle);
                }
                finally
                {
                    if (slot.Drawings is not null)
                    {
                        DebugRecorder.Exit();
                    }

                    if (slot.Log is not null)
                    {
                        ConsoleRouter.Exit();
                    }
                }
            }
            else
            {
                Isolated(slot, slot.Runner, snapshot, cycle);
            }

            slot.WriteDecisions(fish);
        }
    }

    // A call that finished (decided or threw) on another thread or process: its drawings and output count too.
    private static void CopyDrawings(StrategySlot slot, DebugRecorder? from, StrategyLog? log)
    {
        if (slot.Drawings is { } to && from is not null)
        {
            to.AddFrom(from);
        }

        if (slot.Log is { } into && log is not null)
        {
            into.AppendFrom(log);
        }
    }

    // One cycle of a strategy on its own thread in the server's process: waited for as long as its
    // bank lasts, its CPU time measured on its thread.
    private static void Isolated(StrategySlot slot, IsolatedStrategyRunner runner, MatchSnapshot snapshot, int cycle)
    {
        var bank = slot.Bank!;
        var waited = bank.WaitLimit;
        var outcome = runner.Decide(snapshot, slot.Fish, slot.Scratch, bank.CpuLimit, waited, out Exception? error, out TimeSpan cpu, out TimeSpan wall);
        if (outcome == IsolatedStrategyRunner.Outcome.TimedOut)
        {
            GiveUp(slot, cycle, waited, $"no decision within {Seconds(bank.CpuLimit)} of CPU time or {Seconds(waited)}");
            return;
        }

        if (!bank.Charge(cpu, wall))
        {
            Spent(slot, cycle, cpu, wall);
            return;
        }

        if (outcome == IsolatedStrategyRunner.Outcome.Decided)
        {
            slot.Scratch.CopyTo(slot.Decisions, 0);
        }
        else
        {
            slot.ChargeThrown(cycle, error!);
        }

        CopyDrawings(slot, runner.Drawings, runner.Log);
    }

    // A call given up on: no answer while the team's bank (or the call limit) lasted.
    private static void GiveUp(StrategySlot slot, int cycle, TimeSpan waited, string what)
    {
        var bank = slot.Bank!;
        bool limit = bank.WaitEndsAtCallLimit; // before GiveUp empties the bank
        bank.GiveUp(waited);
        slot.OutOfTime(cycle, limit
            ? $"{what} (the limit of one call); the team plays idle for the rest of the match"
            : $"time bank spent: {what}; the team plays idle for the rest of the match");
        if (slot.Hosted is { } hosted)
        {
            hosted.Dispose(); // a host is ended with everything it started
        }
    }

    // A call that answered, but used more than the team's bank had left: its answer does not count.
    private static void Spent(StrategySlot slot, int cycle, TimeSpan? cpu, TimeSpan wall)
    {
        var bank = slot.Bank!;
        string used = cpu is { } c ? $"{Milliseconds(c)} of CPU time and {Milliseconds(wall)}" : Milliseconds(wall);
        slot.OutOfTime(cycle, $"time bank spent: a call took {used} with {Seconds(bank.Reserve)} banked for the match; the team plays idle for the rest of the match");
        slot.Hosted?.Dispose();
    }

    private static string Seconds(TimeSpan t) => string.Create(CultureInfo.InvariantCulture, $"{t.TotalSeconds:0.0##} s");

    private static string Milliseconds(TimeSpan t) => string.Create(CultureInfo.InvariantCulture, $"{t.TotalMilliseconds:0} ms");

    // One cycle of a strategy in another process: the same faults as in the server's process; an
    // ended host stops the team's fish for the rest of the match, a disconnected remote client
    // until a client connects again.
    private void Hosted(StrategySlot slot, IConnectedStrategy hosted, MatchSnapshot snapshot, int cycle)
    {
        ConnectionOutcome outcome;
        string? message;
        var bank = slot.Bank!;
        var waited = bank.WaitLimit;
        long started;
        try
        {
            slot.LastCpuTime ??= hosted.CpuTime();
            slot.LastWaitingTime ??= hosted.WaitingTime();
            started = Stopwatch.GetTimestamp();
            outcome = hosted.Decide(snapshot, slot.Scratch, waited, out message);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // The server failed talking to this host: the team's host is given up, the match goes on.
            slot.Charge(cycle, FaultKind.Ended, $"strategy host ended: the server failed with it: {e.GetType().Name}: {e.Message}");
            return;
        }

        // The time of the call: wall time from the question to the answer; CPU time of the host's whole
        // sandbox since its last answer (what its threads and processes did between calls counts too).
        // The time it waited for a CPU while runnable (a busy machine, measured by the kernel) is not the call's.
        var wall = Stopwatch.GetElapsedTime(started);
        TimeSpan? cpu = null, waiting = null;
        if (outcome is not (ConnectionOutcome.Absent or ConnectionOutcome.Ended or ConnectionOutcome.Disconnected or ConnectionOutcome.GivenUp))
        {
            if (hosted.CpuTime() is { } now)
            {
                cpu = slot.LastCpuTime is { } before ? now - before : null;
                slot.LastCpuTime = now;
            }

            if (hosted.PeakMemoryBytes() is { } peak)
            {
                slot.PeakMemoryBytes = Math.Max(slot.PeakMemoryBytes ?? 0, peak);
            }

            if (hosted.WaitingTime() is { } stalled)
            {
                waiting = slot.LastWaitingTime is { } before ? stalled - before : null;
                slot.LastWaitingTime = stalled;
            }
        }

        if (outcome == ConnectionOutcome.GivenUp)
        {
            GiveUp(slot, cycle, waited, $"no answer within {Seconds(waited)}");
            return;
        }

        if (outcome is ConnectionOutcome.Decided or ConnectionOutcome.Exception or ConnectionOutcome.BadAnswer or ConnectionOutcome.TimedOut && !bank.Charge(cpu, wall, waiting))
        {
            Spent(slot, cycle, cpu, wall);
            return;
        }

        switch (outcome)
        {
            case ConnectionOutcome.Decided:
                slot.Scratch.CopyTo(slot.Decisions, 0);
                CopyDrawings(slot, hosted.Drawings, hosted.Log);
                break;
            case ConnectionOutcome.Exception:
                slot.Charge(cycle, FaultKind.Exception, message ?? "exception");
                CopyDrawings(slot, hosted.Drawings, hosted.Log);
                break;
            case ConnectionOutcome.BadAnswer:
                slot.Charge(cycle, FaultKind.BadAnswer, message ?? "bad answer");
                if (hosted.EndedBy is { } how)
                {
                    Lost(slot, hosted, cycle, how);
                }

                break;
            case ConnectionOutcome.TimedOut:
                slot.Charge(cycle, FaultKind.Timeout, message ?? $"no decision within {TimeoutMs} ms");
                break;
            case ConnectionOutcome.Absent:
                break; // no remote client since a disconnect: nothing asked, nothing charged
            default:
                Lost(slot, hosted, cycle, message ?? "");
                break;
        }
    }

    // The connection has gone: a host for the rest of the match, a remote client until it connects again.
    private static void Lost(StrategySlot slot, IConnectedStrategy hosted, int cycle, string how)
    {
        if (hosted.Reconnects)
        {
            slot.Charge(cycle, FaultKind.Disconnected, $"remote client disconnected: {how}");
        }
        else
        {
            slot.Charge(cycle, FaultKind.Ended, $"strategy host ended: {how}");
        }
    }
}
