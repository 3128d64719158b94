using URWPGSim2D.Engine.Messages;

namespace URWPGSim2D.Engine.Teams;

/// <summary>
/// One strategy's place in a match: the team it plays for, the fish it decides for, the decisions
/// in force, and its faults. How the strategy is run is the owner's business (in process here,
/// <see cref="StrategyTeams"/>; the server adds its threads, hosts and time banks); what a fault
/// does to the match is the same for all: an exception or a bad answer leaves the fish on their
/// last decisions, an ended strategy or one out of time stops them.
/// </summary>
public class TeamSeat
{
    /// <summary>Creates the seat of a strategy for <paramref name="fish"/> of <paramref name="team"/>; every fish starts stopped.</summary>
    /// <param name="spec">What the strategy was asked for as, short ("chase-ball", a path's last part).</param>
    /// <param name="team">The team.</param>
    /// <param name="fish">Indices of the fish it decides for.</param>
    public TeamSeat(string spec, int team, int[] fish)
    {
        ArgumentNullException.ThrowIfNull(spec);
        ArgumentNullException.ThrowIfNull(fish);
        Spec = spec;
        Team = team;
        Fish = fish;
        Decisions = new Decision[fish.Length];
        Scratch = new Decision[fish.Length];
        Array.Fill(Decisions, Decision.Stop);
    }

    /// <summary>What the strategy was asked for as, short: "chase-ball", a path's last part, "remote:PORT".</summary>
    public string Spec { get; }

    /// <summary>How the strategy is shown to people (here its spec).</summary>
    public virtual string Label => Spec;

    /// <summary>Team of its fish.</summary>
    public int Team { get; }

    /// <summary>Indices of the fish it decides for.</summary>
    public int[] Fish { get; }

    /// <summary>The decisions in force, one per fish.</summary>
    public Decision[] Decisions { get; }

    /// <summary>Where a call writes before its result is accepted.</summary>
    public Decision[] Scratch { get; }

    /// <summary>The cycle (1-based) in which the strategy ended (its host ended, or it was found not created), or 0 while it plays.</summary>
    public int EndedInCycle { get; private set; }

    /// <summary>The cycle (1-based) from which the team plays idle because it ran out of time, or 0.</summary>
    public int IdleFromCycle { get; private set; }

    /// <summary>The cycle (1-based) of the latest fault, or 0 for none.</summary>
    public int LastFaultCycle { get; private set; }

    /// <summary>What the latest fault was (<c>exception: …</c>, <c>timeout: …</c>, <c>bad answer: …</c>, <c>ended: …</c>).</summary>
    public string? LastFault { get; private set; }

    /// <summary>The kind of the latest fault.</summary>
    public FaultKind LastFaultKind { get; private set; }

    /// <summary>Cycles in which the strategy threw.</summary>
    public int Exceptions { get; private set; }

    /// <summary>Cycles charged a time-out: its time ran out, a call was given up on, or a remote client reported one.</summary>
    public int Timeouts { get; private set; }

    /// <summary>Cycles in which it answered with something unusable (for example too few decisions).</summary>
    public int BadAnswers { get; private set; }

    /// <summary>Times its remote client disconnected (or was cut off) during the match; counted in <see cref="Crashes"/>.</summary>
    public int Disconnects { get; private set; }

    /// <summary>1 when the strategy ended before the match did (its host crashed, exited or was killed, or it could not be created), plus its disconnects.</summary>
    public int Crashes => (EndedInCycle > 0 ? 1 : 0) + Disconnects;

    /// <summary>All faults: exceptions, time-outs, bad answers and an ended strategy.</summary>
    public int Faults => Exceptions + Timeouts + BadAnswers + Crashes;

    /// <summary>The first fault's message (<c>cycle N: …</c>).</summary>
    public string? FirstFault { get; private set; }

    /// <summary>Whether the strategy is still asked: it has not ended and is not out of time.</summary>
    public bool Plays => EndedInCycle == 0 && IdleFromCycle == 0;

    /// <summary>The strategy's debug drawings of the cycle just decided (none when drawings are not recorded).</summary>
    public virtual ReadOnlySpan<DebugShape> Drawn => default;

    /// <summary>What the strategy printed in the cycle just decided, or null when its output is not recorded.</summary>
    public StrategyLog? Log { get; protected set; }

    /// <summary>Counts a fault of <paramref name="kind"/> in <paramref name="cycle"/> (1-based) and remembers it for the summary and the trace.</summary>
    /// <param name="cycle">The cycle (1-based).</param>
    /// <param name="kind">What went wrong.</param>
    /// <param name="message">What happened, in the strategy's own words where it has any: cleaned of control and escape characters here.</param>
    public void Charge(int cycle, FaultKind kind, string message)
    {
        message = MessageText.Escape(message); // the strategy's own text: no control or escape character reaches a terminal
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

    /// <summary>Charges what a strategy threw in <paramref name="cycle"/>: a <see cref="StrategyContractException"/> is a bad answer, anything else an exception.</summary>
    /// <param name="cycle">The cycle (1-based).</param>
    /// <param name="thrown">What it threw.</param>
    public void ChargeThrown(int cycle, Exception thrown)
    {
        ArgumentNullException.ThrowIfNull(thrown);
        if (thrown is StrategyContractException)
        {
            Charge(cycle, FaultKind.BadAnswer, thrown.Message);
            return;
        }

        Charge(cycle, FaultKind.Exception, $"{thrown.GetType().Name}: {thrown.Message}");
    }

    /// <summary>Charges the time-out that ends the team's time in <paramref name="cycle"/>: its fish stop and it is not asked again this match.</summary>
    /// <param name="cycle">The cycle (1-based).</param>
    /// <param name="message">What happened.</param>
    public void OutOfTime(int cycle, string message)
    {
        Charge(cycle, FaultKind.Timeout, message);
        IdleFromCycle = cycle;
        Array.Fill(Decisions, Decision.Stop);
    }

    /// <summary>Asks <paramref name="strategy"/>, on this thread, for the decisions of the cycle after <paramref name="snapshot"/>'s: they are in force when it answers; when it throws, the fault is charged and the last decisions stay.</summary>
    /// <param name="strategy">The strategy.</param>
    /// <param name="snapshot">What it sees.</param>
    /// <param name="cycle">The cycle the decisions drive (1-based).</param>
    public void DecideInProcess(IStrategy strategy, MatchSnapshot snapshot, int cycle)
    {
        ArgumentNullException.ThrowIfNull(strategy);
        try
        {
            strategy.Decide(snapshot, Fish, Scratch);
            Scratch.CopyTo(Decisions, 0);
        }
        catch (Exception e)
        {
            ChargeThrown(cycle, e);
        }
    }

    /// <summary>Sets the decision of each of its fish in <paramref name="fish"/> to the one in force.</summary>
    /// <param name="fish">The match's fish.</param>
    public void WriteDecisions(FishState[] fish)
    {
        ArgumentNullException.ThrowIfNull(fish);
        for (int k = 0; k < Fish.Length; k++)
        {
            Decision d = Decisions[k];
            fish[Fish[k]].Decision = new Decision(d.VCode, d.TCode);
        }
    }

    /// <summary>Back to the state of a new seat: no decision yet, no fault (a match restarted in place).</summary>
    internal void Restart()
    {
        Array.Fill(Decisions, Decision.Stop);
        Array.Clear(Scratch);
        EndedInCycle = 0;
        IdleFromCycle = 0;
        LastFaultCycle = 0;
        LastFault = null;
        LastFaultKind = default;
        Exceptions = 0;
        Timeouts = 0;
        BadAnswers = 0;
        Disconnects = 0;
        FirstFault = null;
    }
}
