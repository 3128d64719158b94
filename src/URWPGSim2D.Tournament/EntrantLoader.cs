using URWPGSim2D.Hosting;
using URWPGSim2D.Engine.Scenario;

namespace URWPGSim2D.Tournament;

/// <summary>
/// Readies a tournament's entrants once and makes their team strategies for each match, as the
/// <c>run</c> command does (<see cref="StrategyResolver"/>). Readying compiles sources once per
/// tournament and looks up each entrant's strategy class without running any of its code; an entrant
/// that cannot be readied is listed with its one-line reason and forfeits. With
/// <c>--isolation process</c> every user entrant plays each match in a fresh strategy host (a new
/// process: fresh instance and statics); with <c>--isolation none</c> a fresh instance is created in
/// the server's process for each match. Either way a constructor that throws is a fault of that match
/// (charged, the match is played), not a load error. The item's demo strategy is no team strategy
/// (null: the item's layout puts its demo on the team); built-in strategies run in process. Each
/// hosted entrant reserves a pre-started host when it is readied, kept waiting for its next match
/// (<see cref="HostPool.Reserve"/>), so its matches' hosts start warm. A remote entrant
/// (<c>remote:PORT</c>) plays each match with the client on its <see cref="RemoteSeat"/>.
/// </summary>
public sealed class EntrantLoader
{
    private readonly IReadOnlyList<Entrant> _entrants;
    private readonly PreparedStrategy?[] _prepared;
    private readonly string?[] _names;
    private readonly IReadOnlyList<RemoteSeat?>? _seats;

    /// <summary>Readies every entrant under <paramref name="settings"/>.</summary>
    /// <param name="entrants">The entrants, in command-line order.</param>
    /// <param name="settings">How user strategies run (<c>--isolation</c>, <c>--sandbox</c>, <c>--strategy-memory</c>).</param>
    /// <param name="progress">Told a line when an entrant's sources start and finish compiling.</param>
    /// <param name="seats">Per entrant, the seat of a remote entrant (bound by the caller), or null; null for none.</param>
    public EntrantLoader(IReadOnlyList<Entrant> entrants, HostSettings settings, Action<string>? progress = null, IReadOnlyList<RemoteSeat?>? seats = null)
    {
        ArgumentNullException.ThrowIfNull(entrants);
        ArgumentNullException.ThrowIfNull(settings);
        _entrants = entrants;
        _seats = seats;
        Settings = settings;
        _prepared = new PreparedStrategy?[entrants.Count];
        var errors = new string?[entrants.Count];
        var names = new string?[entrants.Count];
        for (int i = 0; i < entrants.Count; i++)
        {
            (_prepared[i], errors[i], names[i]) = Ready(entrants[i], settings, progress);
        }

        for (int i = 0; i < entrants.Count; i++)
        {
            if (entrants[i].RemotePort is not null && seats?[i] is null)
            {
                errors[i] = "a remote entrant needs its seat (remote:PORT is played by the tournament command)";
            }
        }

        Errors = errors;
        _names = names;
        Reserve(settings);
    }

    /// <summary>
    /// Per entrant, the team's own name as its code gives it (the original's <c>GetTeamName()</c> or the
    /// SDK's <c>TeamName</c> when it returns a constant; a built-in strategy's name; for a remote entrant, the
    /// name its last client sent), or null when not known.
    /// </summary>
    public IReadOnlyList<string?> TeamNames
    {
        get
        {
            var names = (string?[])_names.Clone();
            for (int i = 0; i < names.Length; i++)
            {
                names[i] ??= _seats?[i]?.ClientName;
            }

            return names;
        }
    }

    /// <summary>How user strategies run.</summary>
    public HostSettings Settings { get; }

    /// <summary>Per entrant, why it cannot be used (it forfeits), or null.</summary>
    public IReadOnlyList<string?> Errors { get; }

    /// <summary>Whether some entrant runs in strategy hosts (so the sandbox question applies).</summary>
    public bool AnyHosted => Array.Exists(_prepared, p => p is not null);

    /// <summary>
    /// Entrant <paramref name="index"/>'s team strategy for one match (fresh state), or null for the demo.
    /// A constructor that throws (in-process) gives a team whose fault is charged in cycle 1.
    /// </summary>
    /// <exception cref="StrategyLoadException">The entrant can no longer be loaded (its files changed).</exception>
    public TeamStrategy? Create(int index)
    {
        var entrant = _entrants[index];
        if (entrant.Spec == Entrant.Demo)
        {
            return null;
        }

        if (_prepared[index] is { } prepared)
        {
            return TeamStrategy.Hosted(entrant.Name, prepared, Settings);
        }

        if (_seats?[index] is { } seat)
        {
            return TeamStrategy.RemoteClient(entrant.Name, seat);
        }

        return TeamStrategy.InProcess(entrant.Name, entrant.Spec, settings: Settings);
    }

    /// <summary>Reserves again a waiting host for each hosted entrant (after <see cref="Release"/>), kept waiting as when readied.</summary>
    public void Reserve() => Reserve(Settings);

    /// <summary>Ends the hosts waiting for these entrants and keeps none waiting until <see cref="Reserve()"/>: their matches still play, each starting its own host.</summary>
    public void Release()
    {
        foreach (var prepared in _prepared)
        {
            if (prepared is not null)
            {
                HostPool.Release(prepared);
            }
        }
    }

    /// <summary>The process ids of the hosts waiting for these entrants now.</summary>
    public IReadOnlyList<int> WaitingHosts() => [.. _prepared.Where(p => p is not null).SelectMany(p => HostPool.WaitingFor(p!))];

    // A waiting host for each hosted entrant, started now (while the tournament is set up) and replaced whenever taken.
    private void Reserve(HostSettings settings)
    {
        if (!AnyHosted)
        {
            return;
        }

        bool sandbox;
        try
        {
            sandbox = HostSandbox.Use(settings.Sandbox);
        }
        catch (StrategyLoadException)
        {
            return; // --sandbox required and no sandbox here: the tournament refuses to play
        }

        foreach (var prepared in _prepared)
        {
            if (prepared is not null)
            {
                HostPool.Reserve(prepared, settings, sandbox, keep: true);
            }
        }
    }

    /// <summary>The one-line reason of a load failure: the message, and the first compile error when there are some.</summary>
    public static string Reason(StrategyLoadException e) =>
        StandingsText.Line(e.Details.Count == 0 ? e.Message : $"{e.Message.TrimEnd(':', ' ')}; first: {e.Details[0]}");

    // The prepared strategy (hosted entrants) and null, or null and the reason it cannot be used; and the team's own name when known.
    private static (PreparedStrategy? Prepared, string? Error, string? Name) Ready(Entrant entrant, HostSettings settings, Action<string>? progress)
    {
        if (entrant.Spec == Entrant.Demo || entrant.RemotePort is not null)
        {
            return (null, null, null);
        }

        if (System.Linq.Enumerable.Contains(StrategyResolver.BuiltInNames, entrant.Spec))
        {
            return (null, null, entrant.Spec);
        }

        try
        {
            var prepared = StrategyResolver.Prepare(entrant.Spec, progress, settings); // compiles and checks; runs none of the entrant's code
            return (settings.Isolation == IsolationMode.Process ? prepared : null, null, prepared is null ? null : OwnName(prepared));
        }
        catch (StrategyLoadException e)
        {
            return (null, Reason(e), null);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return (null, StandingsText.Line($"{e.GetType().Name}: {e.Message}"), null); // whatever loading throws, the tournament goes on
        }
    }

    // The constant name the strategy's assembly gives its team, read from its metadata (none of its code runs); null when not constant.
    private static string? OwnName(PreparedStrategy prepared)
    {
        int hash = prepared.LoadSpec.LastIndexOf('#');
        string assembly = hash > 0 ? prepared.LoadSpec[..hash] : prepared.LoadSpec;
        try
        {
            return StrategyInspection.Of(assembly).TeamName;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return null; // only shown in the report: an assembly the inspection cannot read still plays
        }
    }
}
