using System.Collections.Specialized;
using System.Text.Json;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;
using URWPGSim2D.Viewer;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The live view's control board (<c>run --live --strategies DIR</c>): what the next match plays —
/// the item, its length and each team's strategy, chosen from the strategies of DIR
/// (<see cref="StrategyCatalog"/>) and the built-in ones — and the strategies loaded for it, exactly
/// as <c>run --strategy</c> loads them (<see cref="RunCommand.LoadTeam"/>: strategy hosts by default).
/// The board owns the choice; the <see cref="LiveMatch"/> owns the match and asks <see cref="Next"/>
/// whenever it builds one. <c>start</c> and <c>recompile</c> are checked and loaded on the
/// requesting thread, one at a time; a refusal (a bad choice, a strategy that does not compile) is
/// the lines the command line prints and leaves the match being played alone.
/// </summary>
internal sealed class LiveBoard
{
    /// <summary>The choice of a team that keeps the scene's own strategies (an item's demo, a scenario file's fish).</summary>
    public const string SceneChoice = "scene";

    /// <summary>The query parameters of <c>start</c>.</summary>
    private static readonly string[] StartParameters = ["action", "item", "minutes", "cycles", "team0", "team1", "team2", "team3"];

    private readonly RunOptions _options;
    private readonly string _folder;
    private readonly CliConsole _console;
    private readonly LiveMatchChoices _choices;
    private readonly object _gate = new(); // guards _current and _fresh
    private readonly object _loading = new(); // one start or recompile at a time
    private Selection _current;
    private bool _fresh = true; // the loaded strategies have not played a match yet

    /// <summary>Creates the board with the command line's choice and its loaded strategies as the first match.</summary>
    /// <param name="options">The run options (<c>--strategies</c>, isolation, seed, …).</param>
    /// <param name="scenario">The command line's scene.</param>
    /// <param name="teams">The command line's loaded strategies.</param>
    /// <param name="console">Where compile progress and refusals are printed (stderr, as the command line does).</param>
    public LiveBoard(RunOptions options, ScenarioDefinition scenario, TeamStrategy?[] teams, CliConsole console)
    {
        _options = options;
        _folder = options.StrategiesFolder ?? throw new ArgumentException("the board needs --strategies DIR", nameof(options));
        _console = console;
        _choices = new LiveMatchChoices(options, scenario);
        var names = new string[4];
        for (int t = 0; t < names.Length; t++)
        {
            names[t] = options.Strategies[t] ?? SceneChoice;
        }

        _current = new Selection(_choices.CommandLine, options.Minutes, options.Cycles, names, scenario, teams);
    }

    /// <summary>Builds the settings of the next match from the current choice (the player's thread calls it at every start).</summary>
    public MatchSettings Next()
    {
        Selection s;
        bool fresh;
        lock (_gate)
        {
            s = _current;
            fresh = _fresh;
            _fresh = false;
        }

        var teams = fresh ? s.Teams : Renewed(s);
        int cycles = s.Cycles ?? (s.Minutes * 600) ?? s.Scenario.Cycles;
        return new MatchSettings(s.Scenario, cycles, _options.Seed, _options.Noise, teams, _options.StrategyTimeoutMs, _options.Threads ?? 1, _options.DebugDraw, _options.StrategyLog, _options.TimeBank);
    }

    /// <summary>
    /// A board action: <c>start</c> (the query's choice, played at once) or <c>recompile</c> (the
    /// current choice with its strategies loaded again from their files, restarted); null for any
    /// other action (the player's own).
    /// </summary>
    /// <param name="action">The action.</param>
    /// <param name="query">The request's query.</param>
    /// <param name="start">Starts the next match and plays it.</param>
    /// <param name="restart">Starts the next match, paused or playing as before.</param>
    public LiveReply? Control(string action, NameValueCollection query, Action start, Action restart)
    {
        if (action is not ("start" or "recompile"))
        {
            return null;
        }

        lock (_loading)
        {
            Selection chosen;
            if (action == "start")
            {
                var (choice, why) = Choose(query);
                if (choice is null)
                {
                    return Refused(why!);
                }

                chosen = choice;
            }
            else
            {
                lock (_gate)
                {
                    chosen = _current;
                }

                foreach (string? key in query.AllKeys)
                {
                    if (key != "action")
                    {
                        return Refused($"recompile: unknown parameter {MessageText.Quote(key ?? string.Empty)} (recompile plays the current choice again)");
                    }
                }
            }

            var progress = new List<string>();
            void Told(string line)
            {
                progress.Add(line);
                _console.ErrorLine(line);
            }

            var loaded = new TeamStrategy?[4];
            for (int t = 0; t < loaded.Length; t++)
            {
                if (chosen.Names[t] == SceneChoice)
                {
                    continue;
                }

                try
                {
                    loaded[t] = RunCommand.LoadTeam(_options, SpecOf(t, chosen.Names[t]), Told);
                }
                catch (StrategyLoadException e)
                {
                    return Refused([$"team {t} ({chosen.Names[t]}): {e.Message}", .. e.Details]);
                }
            }

            lock (_gate)
            {
                _current = chosen with { Teams = loaded };
                _fresh = true;
            }

            (action == "start" ? start : restart)();
            return progress.Count == 0 ? LiveReply.Done : new LiveReply(200, string.Concat(progress.Select(l => l + "\n")));
        }
    }

    /// <summary>The board's choices and the current choice, as <c>GET /board</c> serves them (docs/viewer.md).</summary>
    public string Json()
    {
        Selection s;
        lock (_gate)
        {
            s = _current;
        }

        var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer))
        {
            w.WriteStartObject();
            w.WriteString("folder", _folder);
            w.WriteStartArray("items");
            foreach (var item in _choices.Items)
            {
                w.WriteStartObject();
                w.WriteString("id", item.Id);
                w.WriteString("name", item.Name);
                w.WriteNumber("teams", item.Teams);
                w.WriteNumber("cycles", item.Cycles);
                w.WriteBoolean("demo", item.HasDemo);
                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteStartArray("minutes");
            foreach (int m in LiveMatchChoices.Minutes)
            {
                w.WriteNumberValue(m);
            }

            w.WriteEndArray();
            w.WriteStartArray("builtIns");
            foreach (string name in BuiltIns)
            {
                w.WriteStringValue(name);
            }

            w.WriteEndArray();
            w.WriteStartArray("strategies");
            foreach (string name in StrategyCatalog.Scan(_folder))
            {
                w.WriteStringValue(name);
            }

            w.WriteEndArray();
            w.WriteStartArray("commandLine");
            foreach (string? spec in _options.Strategies)
            {
                w.WriteStringValue(spec);
            }

            w.WriteEndArray();
            w.WriteStartObject("current");
            w.WriteString("item", s.Item.Id);
            WriteNumberOrNull(w, "minutes", s.Minutes);
            WriteNumberOrNull(w, "cycles", s.Cycles);
            w.WriteStartArray("teams");
            for (int t = 0; t < s.Item.Teams; t++)
            {
                w.WriteStringValue(s.Names[t]);
            }

            w.WriteEndArray();
            w.WriteEndObject();
            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(buffer.ToArray());
    }

    /// <summary>The built-in choices of a team, in the board's order.</summary>
    public static IReadOnlyList<string> BuiltIns { get; } = [SceneChoice, TeamStrategy.DemoSpec, .. StrategyResolver.BuiltInNames];

    private static void WriteNumberOrNull(Utf8JsonWriter w, string name, int? value)
    {
        if (value is int v)
        {
            w.WriteNumber(name, v);
        }
        else
        {
            w.WriteNull(name);
        }
    }

    private LiveReply Refused(params string[] lines)
    {
        foreach (string line in lines)
        {
            _console.ErrorLine(line);
        }

        return LiveReply.Refused(lines);
    }

    // The choice a start asks for, checked; or why not (one line naming the parameter and its value).
    private (Selection? Choice, string? Why) Choose(NameValueCollection query)
    {
        foreach (string? key in query.AllKeys)
        {
            if (key is null || !StartParameters.Contains(key, StringComparer.Ordinal))
            {
                return (null, $"start: unknown parameter {MessageText.Quote(key ?? string.Empty)} (item, minutes, cycles, team0 … team3)");
            }
        }

        Selection current;
        lock (_gate)
        {
            current = _current;
        }

        var item = current.Item;
        if (query["item"] is { } itemName)
        {
            if (_choices.Find(itemName) is not { } found)
            {
                return (null, $"start: item {MessageText.Quote(itemName)} is not an item of the board ({string.Join(", ", _choices.Items.Select(i => i.Id))})");
            }

            item = found;
        }

        int? minutes = null, cycles = null;
        if (query["minutes"] is { Length: > 0 } m)
        {
            minutes = m switch { "10" => 10, "5" => 5, "3" => 3, "1" => 1, _ => (int?)null };
            if (minutes is null)
            {
                return (null, $"start: minutes must be 10, 5, 3 or 1, got {MessageText.Quote(m)}");
            }
        }

        if (query["cycles"] is { Length: > 0 } c)
        {
            if (!int.TryParse(c, NumberStyles.None, CultureInfo.InvariantCulture, out int n))
            {
                return (null, $"start: cycles must be an integer 0..{int.MaxValue}, got {MessageText.Quote(c)}");
            }

            cycles = n;
        }

        if (minutes is not null && cycles is not null)
        {
            return (null, "start: minutes and cycles both set the length; give one");
        }

        var names = new string[4];
        var catalog = StrategyCatalog.Scan(_folder);
        for (int t = 0; t < names.Length; t++)
        {
            string name = query["team" + t.ToString(CultureInfo.InvariantCulture)] ?? SceneChoice;
            if (t >= item.Teams && name != SceneChoice)
            {
                return (null, $"start: team{t}: {item.Id} has no team {t} (teams 0 to {item.Teams - 1})");
            }

            bool known = BuiltIns.Contains(name, StringComparer.Ordinal) || catalog.Contains(name, StringComparer.Ordinal) || name == _options.Strategies[t];
            if (!known)
            {
                return (null, $"start: team{t}: {MessageText.Quote(name)} is not a strategy of {_folder} (there: {(catalog.Count == 0 ? "none" : string.Join(", ", catalog))}) nor a built-in one ({string.Join(", ", BuiltIns)})");
            }

            if (name == TeamStrategy.DemoSpec && !item.HasDemo)
            {
                return (null, $"start: team{t}: demo is the demo strategy of a competition item, and {item.Id} is not one");
            }

            names[t] = name;
        }

        return (new Selection(item, minutes, cycles, names, item.Create(), new TeamStrategy?[4]), null);
    }

    // The spec --strategy takes for team t's choice (the board checked it is one of the offered names).
    private string SpecOf(int team, string name) =>
        BuiltIns.Contains(name, StringComparer.Ordinal) || name == _options.Strategies[team] ? name : StrategyCatalog.Spec(_folder, name);

    // Strategies for a restarted match: a host starts afresh with every match; a strategy in the
    // server's process (a built-in, or --isolation none) is created again so its state starts over.
    private TeamStrategy?[] Renewed(Selection s)
    {
        var teams = (TeamStrategy?[])s.Teams.Clone();
        for (int t = 0; t < teams.Length; t++)
        {
            if (teams[t] is { Strategy: not null } or { NotCreated: not null })
            {
                try
                {
                    teams[t] = RunCommand.LoadTeam(_options, SpecOf(t, s.Names[t]));
                }
                catch (StrategyLoadException)
                {
                    // The files vanished since: the strategy plays on as loaded.
                }
            }
        }

        return teams;
    }

    /// <summary>What a match of the board plays.</summary>
    /// <param name="Item">The item (or scene).</param>
    /// <param name="Minutes">The length in minutes, or null.</param>
    /// <param name="Cycles">The length in cycles, or null (neither: the scene's).</param>
    /// <param name="Names">Per team, the board's name of its choice.</param>
    /// <param name="Scenario">The item's scene.</param>
    /// <param name="Teams">Per team, the loaded strategy (null: the scene's own).</param>
    private sealed record Selection(LiveMatchChoices.Choice Item, int? Minutes, int? Cycles, string[] Names, ScenarioDefinition Scenario, TeamStrategy?[] Teams);
}
