namespace URWPGSim2D.Hosting;

/// <summary>
/// One strategy instance and the fish it controls, with its last decisions and fault counts.
/// Built-in strategies run inline; loaded (user) strategies run isolated on their own thread with
/// a time limit, or in a strategy host process (<see cref="Hosted"/>).
/// </summary>
public sealed class StrategySlot : TeamSeat
{
    /// <summary>A slot whose strategy runs in the server's process.</summary>
    public StrategySlot(string label, IStrategy strategy, int team, int[] fish, bool isolated, StrategyClock? clock = null)
        : this(label, team, fish)
    {
        Strategy = strategy;
        Runner = isolated ? new IsolatedStrategyRunner(strategy, fish.Length, team, clock ?? new ThreadTimeClock()) : null;
    }

    /// <summary>A slot whose strategy plays over the strategy protocol: in a strategy host process or on a remote client.</summary>
    internal StrategySlot(string label, IConnectedStrategy hosted, int team, int[] fish)
        : this(label, team, fish)
    {
        Hosted = hosted;
    }

    /// <summary>A slot whose strategy (in the server's process) could not be created: charged in cycle 1, its fish stop.</summary>
    public static StrategySlot NotCreated(string label, string why, int team, int[] fish) => new(label, team, fish) { CreationFault = why };

    private StrategySlot(string label, int team, int[] fish)
        : base(label, team, fish)
    {
    }

    /// <summary>
    /// The strategy's own name, once it is known: the hello of a strategy host (before the match)
    /// or of a remote client (when it connects); null before, and in the server's process, where
    /// the label given holds the name already (<see cref="TeamStrategy.InProcess"/>).
    /// </summary>
    public string? Name => TeamName.Clean(Hosted?.TeamName);

    /// <summary>How the team is shown: the strategy's own name with the spec beside it (<see cref="TeamName.Label"/>).</summary>
    public override string Label => TeamName.Label(Name, Spec);

    /// <summary>The strategy (in the server's process), or null for a hosted one.</summary>
    public IStrategy? Strategy { get; }

    /// <summary>The connection of a strategy that runs in another process (a strategy host or a remote client), or null.</summary>
    internal IConnectedStrategy? Hosted { get; }

    /// <summary>Why the strategy could not be created in the server's process, or null.</summary>
    public string? CreationFault { get; private init; }

    /// <summary>The worker thread for an isolated strategy, else null.</summary>
    internal IsolatedStrategyRunner? Runner { get; }

    /// <summary>The strategy's debug drawings of the cycle just decided, or null when drawings are not recorded.</summary>
    internal DebugRecorder? Drawings { get; private set; }

    /// <inheritdoc/>
    public override ReadOnlySpan<DebugShape> Drawn => Drawings is { } d ? d.Shapes : default;

    /// <summary>Records the strategy's debug drawings from now on (<c>run --debug-draw</c>).</summary>
    public void RecordDrawings()
    {
        Drawings ??= new DebugRecorder();
        Runner?.RecordDrawings();
    }

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

    /// <summary>The most memory its host's sandbox held at once, bytes, as of its last answer; null where it is not measured (in the server's process, a remote client, no control group).</summary>
    public long? PeakMemoryBytes { get; set; }
}
