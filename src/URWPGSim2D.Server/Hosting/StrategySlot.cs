using System;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// One strategy instance and the fish it controls, with its last decisions and fault counts.
/// Built-in strategies run inline; loaded (user) strategies run isolated on their own thread with
/// a time limit.
/// </summary>
internal sealed class StrategySlot
{
    public StrategySlot(string label, IStrategy strategy, int team, int[] fish, bool isolated, StrategyClock? clock = null)
    {
        Label = label;
        Strategy = strategy;
        Team = team;
        Fish = fish;
        Decisions = new Decision[fish.Length];
        Scratch = new Decision[fish.Length];
        Array.Fill(Decisions, Decision.Stop);
        Runner = isolated ? new IsolatedStrategyRunner(strategy, fish.Length, team, clock ?? new ThreadTimeClock()) : null;
    }

    /// <summary>What the user asked for ("chase-ball", a path...).</summary>
    public string Label { get; }

    /// <summary>The strategy.</summary>
    public IStrategy Strategy { get; }

    /// <summary>Team of its fish.</summary>
    public int Team { get; }

    /// <summary>Indices of the fish it controls.</summary>
    public int[] Fish { get; }

    /// <summary>The decisions in force, one per fish.</summary>
    public Decision[] Decisions { get; }

    /// <summary>Where a call writes before its result is accepted.</summary>
    public Decision[] Scratch { get; }

    /// <summary>The worker thread for an isolated strategy, else null.</summary>
    public IsolatedStrategyRunner? Runner { get; }

    /// <summary>Cycles in which the strategy threw.</summary>
    public int Exceptions { get; set; }

    /// <summary>Cycles in which it ran past its time limit (or was still busy from an earlier one).</summary>
    public int Timeouts { get; set; }

    /// <summary>Cycles in which it answered with something unusable (for example too few decisions).</summary>
    public int BadAnswers { get; set; }

    /// <summary>All faults: exceptions, time-outs and bad answers.</summary>
    public int Faults => Exceptions + Timeouts + BadAnswers;

    /// <summary>The first fault's message.</summary>
    public string? FirstFault { get; set; }
}
