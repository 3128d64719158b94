using URWPGSim2D.Hosting;

namespace URWPGSim2D.Hosting;

/// <summary>A strategy that takes over a whole team (from <c>--strategy TEAM=path</c> or a test).</summary>
/// <param name="Label">What to call it in the summary.</param>
/// <param name="Strategy">The strategy instance (in the server's process), or null when <paramref name="Host"/> or <paramref name="NotCreated"/> is given.</param>
/// <param name="Isolated">Run it on its own thread with a time limit (loaded strategies always are).</param>
/// <param name="Clock">The deadline clock of an isolated strategy (null: its thread's CPU time; tests pass a <see cref="ManualStrategyClock"/>).</param>
/// <param name="Host">A strategy for strategy host processes: every match built with it starts a fresh host.</param>
/// <param name="Settings">The hosts' sandbox and memory settings (null: the defaults).</param>
/// <param name="NotCreated">Why the strategy (in the server's process) could not be created: its constructor or static constructor threw. The team's fault, charged in cycle 1; its fish stop.</param>
/// <param name="Remote">The seat of a team played by a remote client, or null.</param>
/// <param name="Demo">The item's demo strategy plays the whole team (<c>--strategy TEAM=demo</c>).</param>
public sealed record TeamStrategy(string Label, IStrategy? Strategy, bool Isolated, StrategyClock? Clock = null, PreparedStrategy? Host = null, HostSettings? Settings = null, string? NotCreated = null, RemoteSeat? Remote = null, bool Demo = false)
{
    /// <summary>The spec of the item's demo strategy: <c>--strategy TEAM=demo</c>.</summary>
    public const string DemoSpec = "demo";

    /// <summary>The item's demo strategy for the whole team (the scene must be a competition item).</summary>
    public static TeamStrategy ItemDemo { get; } = new(DemoSpec, null, false, Demo: true);

    /// <summary>A team played by a remote client on <paramref name="seat"/>.</summary>
    public static TeamStrategy RemoteClient(string label, RemoteSeat seat) => new(label, null, true, Remote: seat);

    /// <summary>A team played by a strategy host process per match.</summary>
    public static TeamStrategy Hosted(string label, PreparedStrategy host, HostSettings settings) => new(label, null, true, null, host, settings);

    /// <summary>
    /// A team played in the server's process by a fresh instance of <paramref name="spec"/>
    /// (<c>--isolation none</c>): isolated on its own thread; a constructor that throws is the team's fault, not a load error.
    /// </summary>
    /// <param name="label">The spec's label, for a strategy that has no name of its own.</param>
    /// <param name="spec">The spec.</param>
    /// <param name="progress">Told when sources start and finish compiling.</param>
    /// <param name="settings">The limits of the compiler's child process (null: the defaults).</param>
    /// <exception cref="StrategyLoadException">The strategy cannot be loaded (not found, does not compile, no strategy class).</exception>
    public static TeamStrategy InProcess(string label, string spec, Action<string>? progress = null, HostSettings? settings = null)
    {
        try
        {
            IStrategy strategy = StrategyResolver.Load(spec, progress, settings);
            return new TeamStrategy(Hosting.TeamName.Label(NameOf(strategy), label), strategy, Isolated: true);
        }
        catch (StrategyCreationException e)
        {
            return new TeamStrategy(label, null, Isolated: true, NotCreated: e.Message);
        }
    }

    // In the server's process the strategy's constructor has run on this thread already; its name
    // is read here too, once (a name that throws is no name).
    private static string? NameOf(IStrategy strategy)
    {
        try
        {
            return Hosting.TeamName.Clean(strategy.TeamName);
        }
        catch (Exception)
        {
            return null;
        }
    }
}
