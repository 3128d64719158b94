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

    /// <summary>Ends the threads of the isolated strategies (after the match).</summary>
    public void Stop()
    {
        foreach (var slot in Slots)
        {
            slot.Runner?.Stop();
        }
    }

    /// <summary>Runs every strategy on <paramref name="snapshot"/> and writes the fish's decisions.</summary>
    public void Decide(MatchSnapshot snapshot, FishState[] fish)
    {
        foreach (var slot in Slots)
        {
            slot.Decisions.CopyTo(slot.Scratch, 0);
            if (slot.Runner is null)
            {
                try
                {
                    slot.Strategy.Decide(snapshot, slot.Fish, slot.Scratch);
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
