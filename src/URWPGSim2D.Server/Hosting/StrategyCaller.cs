using System;
using System.Collections.Generic;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// Asks every strategy slot, in a fixed order, for its fish's decisions. A strategy that throws,
/// answers with something unusable (<see cref="StrategyContractException"/>) or (isolated ones) runs
/// past its deadline leaves its fish on their last decisions; the fault is counted for the summary
/// and the results file, and the match goes on.
/// </summary>
internal sealed class StrategyCaller(StrategySlot[] slots, int timeoutMs)
{
    /// <summary>The slots, in decision order.</summary>
    public StrategySlot[] Slots { get; } = slots;

    private string? _timeoutText;

    /// <summary>Time limit of an isolated strategy per cycle, ms.</summary>
    public int TimeoutMs { get; } = timeoutMs;

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
                slot.Hosted?.Stop(new Protocol.EndMessage(cycles, end, slot.Faults));
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
            if (slot.EndedInCycle > 0)
            {
                // its host has ended (or it was never created): its fish stay stopped
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
                    slot.Strategy!.Decide(snapshot, slot.Fish, slot.Scratch);
                    slot.Scratch.CopyTo(slot.Decisions, 0);
                }
                catch (Exception e)
                {
                    Fault(slot, cycle, e);
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
                switch (slot.Runner.Decide(snapshot, slot.Fish, slot.Scratch, TimeoutMs, out Exception? error))
                {
                    case IsolatedStrategyRunner.Outcome.Decided:
                        slot.Scratch.CopyTo(slot.Decisions, 0);
                        CopyDrawings(slot, slot.Runner.Drawings, slot.Runner.Log);
                        break;
                    case IsolatedStrategyRunner.Outcome.Threw:
                        Fault(slot, cycle, error!);
                        CopyDrawings(slot, slot.Runner.Drawings, slot.Runner.Log);
                        break;
                    default:
                        slot.Charge(cycle, FaultKind.Timeout, TimeoutText);
                        break;
                }
            }

            for (int k = 0; k < slot.Fish.Length; k++)
            {
                Decision d = slot.Decisions[k];
                fish[slot.Fish[k]].Decision = new Decision(d.VCode, d.TCode);
            }
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

    private string TimeoutText => _timeoutText ??= $"no decision within {TimeoutMs} ms";

    // One cycle of a strategy in another process: the same faults as in the server's process; an
    // ended host stops the team's fish for the rest of the match, a disconnected remote client
    // until a client connects again.
    private void Hosted(StrategySlot slot, IConnectedStrategy hosted, MatchSnapshot snapshot, int cycle)
    {
        ConnectionOutcome outcome;
        string? message;
        try
        {
            outcome = hosted.Decide(snapshot, slot.Scratch, out message);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // The server failed talking to this host: the team's host is given up, the match goes on.
            slot.Charge(cycle, FaultKind.Ended, $"strategy host ended: the server failed with it: {e.GetType().Name}: {e.Message}");
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
                slot.Charge(cycle, FaultKind.Timeout, TimeoutText);
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

    private static void Fault(StrategySlot slot, int cycle, Exception e)
    {
        if (e is StrategyContractException)
        {
            slot.Charge(cycle, FaultKind.BadAnswer, e.Message);
            return;
        }

        slot.Charge(cycle, FaultKind.Exception, $"{e.GetType().Name}: {e.Message}");
    }
}
