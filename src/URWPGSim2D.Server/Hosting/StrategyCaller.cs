using System;
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

    private (int Cycle, int Goals0, int Goals1) _last;

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
    /// <param name="goals0">Team 0's final score.</param>
    /// <param name="goals1">Team 1's final score.</param>
    public void Stop(int cycles, int goals0, int goals1)
    {
        foreach (var slot in Slots)
        {
            slot.Runner?.Stop();
            slot.Hosted?.Stop(new Protocol.EndMessage(cycles, goals0, goals1, slot.Faults));
        }
    }

    /// <summary>Ends the threads of the isolated strategies and the strategy hosts, with the score of the last cycle's snapshot.</summary>
    public void Stop() => Stop(_last.Cycle, _last.Goals0, _last.Goals1);

    /// <summary>Runs every strategy on <paramref name="snapshot"/> and writes the fish's decisions.</summary>
    public void Decide(MatchSnapshot snapshot, FishState[] fish)
    {
        _last = (snapshot.Cycle + 1, snapshot.GoalsOf(0), snapshot.GoalsOf(1));
        foreach (var slot in Slots)
        {
            slot.Decisions.CopyTo(slot.Scratch, 0);
            if (slot.Hosted is { } hosted)
            {
                Hosted(slot, hosted, snapshot);
            }
            else if (slot.Runner is null)
            {
                try
                {
                    slot.Strategy!.Decide(snapshot, slot.Fish, slot.Scratch);
                    slot.Scratch.CopyTo(slot.Decisions, 0);
                }
                catch (Exception e)
                {
                    Fault(slot, snapshot.Cycle, e);
                }
            }
            else
            {
                switch (slot.Runner.Decide(snapshot, slot.Fish, slot.Scratch, TimeoutMs, out Exception? error))
                {
                    case IsolatedStrategyRunner.Outcome.Decided:
                        slot.Scratch.CopyTo(slot.Decisions, 0);
                        break;
                    case IsolatedStrategyRunner.Outcome.Threw:
                        Fault(slot, snapshot.Cycle, error!);
                        break;
                    default:
                        slot.Timeouts++;
                        slot.FirstFault ??= $"cycle {snapshot.Cycle + 1}: no decision within {TimeoutMs} ms";
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

    // One cycle of a strategy in another process: the same faults as in the server's process; an
    // ended host stops the team's fish for the rest of the match, a disconnected remote client
    // until it connects again.
    private void Hosted(StrategySlot slot, IConnectedStrategy hosted, MatchSnapshot snapshot)
    {
        if (slot.EndedInCycle > 0)
        {
            return;
        }

        int cycle = snapshot.Cycle + 1;
        switch (hosted.Decide(snapshot, slot.Scratch, out string? message))
        {
            case ConnectionOutcome.Decided:
                slot.Scratch.CopyTo(slot.Decisions, 0);
                break;
            case ConnectionOutcome.Exception:
                slot.Exceptions++;
                slot.FirstFault ??= $"cycle {cycle}: {message}";
                break;
            case ConnectionOutcome.BadAnswer:
                slot.BadAnswers++;
                slot.FirstFault ??= $"cycle {cycle}: {message}";
                break;
            case ConnectionOutcome.TimedOut:
                slot.Timeouts++;
                slot.FirstFault ??= $"cycle {cycle}: no decision within {TimeoutMs} ms";
                break;
            case ConnectionOutcome.Disconnected:
                slot.Disconnects++;
                slot.FirstFault ??= $"cycle {cycle}: remote client disconnected: {message}";
                Array.Fill(slot.Decisions, Decision.Stop);
                break;
            case ConnectionOutcome.Absent:
                break; // no client since a disconnect: its fish stay stopped
            default:
                slot.EndedInCycle = cycle;
                slot.FirstFault ??= $"cycle {cycle}: strategy host ended: {message}";
                Array.Fill(slot.Decisions, Decision.Stop);
                break;
        }
    }

    private static void Fault(StrategySlot slot, int cycle, Exception e)
    {
        if (e is StrategyContractException)
        {
            slot.BadAnswers++;
            slot.FirstFault ??= $"cycle {cycle + 1}: {e.Message}";
            return;
        }

        slot.Exceptions++;
        slot.FirstFault ??= $"cycle {cycle + 1}: {e.GetType().Name}: {e.Message}";
    }
}
