using System;
using URWPGSim2D.Server.Teams;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// One strategy instance and the fish it controls, with its last decisions and fault counts.
/// Built-in strategies run inline; loaded (user) strategies run isolated on their own thread with
/// a time limit, or in a strategy host process (<see cref="Hosted"/>).
/// </summary>
internal sealed class StrategySlot : ITeamSeat
{
    /// <summary>A slot whose strategy runs in the server's process.</summary>
    public StrategySlot(string label, IStrategy strategy, int team, int[] fish, bool isolated, StrategyClock? clock = null)
        : this(label, team, fish)
    {
        Strategy = strategy;
        Runner = isolated ? new IsolatedStrategyRunner(strategy, fish.Length, team, clock ?? new ThreadTimeClock()) : null;
    }

    /// <summary>A slot whose strategy plays over the strategy protocol: in a strategy host process or on a remote client.</summary>
    public StrategySlot(string label, IConnectedStrategy hosted, int team, int[] fish)
        : this(label, team, fish)
    {
        Hosted = hosted;
    }

    /// <summary>A slot whose strategy (in the server's process) could not be created: charged in cycle 1, its fish stop.</summary>
    public static StrategySlot NotCreated(string label, string why, int team, int[] fish) => new(label, team, fish) { CreationFault = why };

    private StrategySlot(string label, int team, int[] fish)
    {
        Spec = label;
        Team = team;
        Fish = fish;
        Decisions = new Decision[fish.Length];
        Scratch = new Decision[fish.Length];
        Array.Fill(Decisions, Decision.Stop);
    }

    /// <summary>What the user asked for, short: "chase-ball", a path's last part, "remote:PORT".</summary>
    public string Spec { get; }

    /// <summary>
    /// The strategy's own name, once it is known: the hello of a strategy host (before the match)
    /// or of a remote client (when it connects); null before, and in the server's process, where
    /// the label given holds the name already (<see cref="TeamStrategy.InProcess"/>).
    /// </summary>
    public string? Name => TeamName.Clean(Hosted?.TeamName);

    /// <summary>How the team is shown: the strategy's own name with the spec beside it (<see cref="TeamName.Label"/>).</summary>
    public string Label => TeamName.Label(Name, Spec);

    /// <summary>The strategy (in the server's process), or null for a hosted one.</summary>
    public IStrategy? Strategy { get; }

    /// <summary>The connection of a strategy that runs in another process (a strategy host or a remote client), or null.</summary>
    public IConnectedStrategy? Hosted { get; }

    /// <summary>Why the strategy could not be created in the server's process, or null.</summary>
    public string? CreationFault { get; private init; }

    /// <summary>The cycle (1-based) in which the strategy host ended (or the strategy was found not created), or 0 while it runs.</summary>
    public int EndedInCycle { get; private set; }

    /// <summary>The cycle (1-based) of the latest fault, or 0 for none.</summary>
    public int LastFaultCycle { get; private set; }

    /// <summary>What the latest fault was (<c>exception: …</c>, <c>timeout: …</c>, <c>bad answer: …</c>, <c>ended: …</c>).</summary>
    public string? LastFault { get; private set; }

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
    public int Exceptions { get; private set; }

    /// <summary>Cycles charged a time-out: its time bank ran out, a call was given up on, or a remote client reported one.</summary>
    public int Timeouts { get; private set; }

    /// <summary>Cycles in which it answered with something unusable (for example too few decisions).</summary>
    public int BadAnswers { get; private set; }

    /// <summary>1 when its strategy host ended before the match did (crashed, exited, was killed, or its strategy could not be created, in a host or in process), else 0.</summary>
    public int Crashes => (EndedInCycle > 0 ? 1 : 0) + Disconnects;

    /// <summary>Times its remote client disconnected (or was cut off) during the match; counted in <see cref="Crashes"/>.</summary>
    public int Disconnects { get; private set; }

    /// <summary>All faults: exceptions, time-outs, bad answers and an ended host.</summary>
    public int Faults => Exceptions + Timeouts + BadAnswers + Crashes;

    /// <summary>The first fault's message (<c>cycle N: …</c>).</summary>
    public string? FirstFault { get; private set; }

    /// <summary>Counts a fault of <paramref name="kind"/> in <paramref name="cycle"/> (1-based) and remembers it for the summary and the trace.</summary>
    public void Charge(int cycle, FaultKind kind, string message)
    {
        message = Json.MessageText.Escape(message); // the strategy's own text: no control or escape character reaches a terminal
        switch (kind)
        {
            case FaultKind.Exception: Exceptions++; break;
            case FaultKind.Timeout: Timeouts++; break;
            case FaultKind.BadAnswer: BadAnswers++; break;
            case FaultKind.Disconnected:
                Disconnects++;
                Array.Fill(Decisions, Decision.Stop);
                break;
            default:
                EndedInCycle = cycle;
                Array.Fill(Decisions, Decision.Stop);
                break;
        }

        FirstFault ??= $"cycle {cycle}: {message}";
        LastFaultCycle = cycle;
        LastFault = message;
        LastFaultKind = kind;
    }

    /// <summary>The strategy's debug drawings of the cycle just decided, or null when drawings are not recorded.</summary>
    public DebugRecorder? Drawings { get; private set; }

    /// <summary>Records the strategy's debug drawings from now on (<c>run --debug-draw</c>).</summary>
    public void RecordDrawings()
    {
        Drawings ??= new DebugRecorder();
        Runner?.RecordDrawings();
    }

    /// <summary>What the strategy printed in the cycle just decided, or null when its output is not recorded.</summary>
    public StrategyLog? Log { get; private set; }

    /// <summary>Records what the strategy prints from now on (<c>run --strategy-log</c>; routes the process's console, <see cref="ConsoleRouter"/>).</summary>
    public void RecordLog()
    {
        ConsoleRouter.Install();
        Log ??= new StrategyLog();
        Runner?.RecordLog();
    }

    /// <summary>The team's time for the match (a strategy that runs isolated or in another process), or null for a built-in one.</summary>
    public TimeBank? Bank { get; set; }

    /// <summary>The CPU time of the strategy's host at its last answer (where it is measured), or null.</summary>
    public TimeSpan? LastCpuTime { get; set; }

    /// <summary>How long the strategy's host had waited for a CPU at its last answer (where it is measured), or null.</summary>
    public TimeSpan? LastWaitingTime { get; set; }

    /// <summary>The cycle (1-based) from which the team plays idle because it ran out of time, or 0.</summary>
    public int IdleFromCycle { get; private set; }

    /// <summary>Charges the time-out that ends the team's time in <paramref name="cycle"/>: its fish stop and it is not asked again this match.</summary>
    /// <param name="cycle">The cycle (1-based).</param>
    /// <param name="message">What happened.</param>
    public void OutOfTime(int cycle, string message)
    {
        Charge(cycle, FaultKind.Timeout, message);
        IdleFromCycle = cycle;
        Array.Fill(Decisions, Decision.Stop);
    }

    /// <summary>The kind of the latest fault.</summary>
    public FaultKind LastFaultKind { get; private set; }
}
