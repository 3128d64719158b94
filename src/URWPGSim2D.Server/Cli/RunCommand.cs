using System.Diagnostics;
using System.Security.Cryptography;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Server.Rendering;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;
using URWPGSim2D.Engine.Trace;
using URWPGSim2D.Tournament.Batch;
using URWPGSim2D.Viewer;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>run</c>: plays a match (the embedded default match, or <c>--scenario FILE</c>) and prints a
/// summary; optionally writes a JSON Lines trace and an SVG of the final frame. A progress bar is
/// drawn only when standard output is a terminal. Bad input (arguments, scenario, strategy
/// assembly) is one line on stderr and exit code 2, with no output file written.
/// </summary>
internal sealed class RunCommand : ICliCommand
{
    /// <summary>The item <c>run</c> plays without a scene option (the README's main job).</summary>
    public const string MainItem = "ball-grab";

    /// <inheritdoc/>
    public string Name => "run";

    /// <inheritdoc/>
    public string Synopsis => RunOptions.Synopsis;

    /// <inheritdoc/>
    public string Summary => "Play a match (default: the competition item ball-grab, 10 minutes) and print a summary.";

    /// <inheritdoc/>
    public Command Syntax => RunSyntax.Command;

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        var options = RunOptions.Parse(words);
        if (options.Help)
        {
            console.Out.Write(HelpText());
            return ExitCodes.Success;
        }

        if (options.ListItems)
        {
            console.Out.Write(ItemList.Format());
            return ExitCodes.Success;
        }

        OutputFile.CheckNew("--trace", options.Trace, options.Force);
        OutputFile.CheckNew("--html", options.Html, options.Force);
        OutputFile.Check("--svg", options.Svg);
        OutputFile.CheckNew("--results", options.Slurm is null ? options.Results : null, options.Force); // with --slurm, FILE may be in DIR, made later (SlurmRun checks it)
        if (options.StrategiesFolder is { } folder && !Directory.Exists(folder))
        {
            console.ErrorLine($"run: --strategies {MessageText.Quote(folder)}: no such folder");
            return ExitCodes.BadInput;
        }

        ScenarioDefinition scenario;
        string scene;
        try
        {
            (scenario, scene) = LoadScene(options, console);
        }
        catch (ScenarioException e)
        {
            console.ErrorLine(e.Message);
            return ExitCodes.BadInput;
        }

        int sceneTeams = 2;
        foreach (var f in scenario.Fish)
        {
            sceneTeams = Math.Max(sceneTeams, f.Team + 1);
        }

        for (int t = sceneTeams; t < options.Strategies.Length; t++)
        {
            if (options.Strategies[t] is not null)
            {
                console.ErrorLine($"run: --strategy {t}: the scene has no team {t} (teams 0 to {sceneTeams - 1})");
                return ExitCodes.BadInput;
            }
        }

        for (int t = 0; t < options.Strategies.Length; t++)
        {
            if (options.Strategies[t] == TeamStrategy.DemoSpec && scenario.Item is null)
            {
                console.ErrorLine($"run: --strategy {t}: demo is the demo strategy of a competition item, and this scene is not one (give --item NAME)");
                return ExitCodes.BadInput;
            }
        }

        TeamStrategy?[] teams;
        HostSandbox.Warn = console.ErrorLine;
        try
        {
            teams = LoadTeams(options, console, console.ErrorLine);
        }
        catch (StrategyLoadException e)
        {
            foreach (string line in e.Lines)
            {
                console.ErrorLine(line); // compile errors: one line each
            }

            return ExitCodes.BadInput;
        }

        if (options.Batch is not null)
        {
            return BatchRun.Run(options, scenario, scene, console);
        }

        try
        {
            return options.Live ? LiveRun.Run(options, scenario, teams, console) : Play(options, scenario, teams, console);
        }
        finally
        {
            foreach (var team in teams)
            {
                team?.Remote?.Dispose();
            }
        }
    }

    // One match: waits for its remote clients, plays it, writes what was asked for and the summary.
    private static int Play(RunOptions options, ScenarioDefinition scenario, TeamStrategy?[] teams, CliConsole console)
    {
        var settings = Settings(options, scenario, teams);
        Match match = settings.Build();
        try
        {
            match.Caller().ConnectRemoteTeams();
        }
        catch (RemoteWaitException e)
        {
            match.Teams.Stop();
            console.ErrorLine(e.Message);
            return ExitCodes.BadInput;
        }

        bool interactive = ReferenceEquals(console.Out, Console.Out) && !Console.IsOutputRedirected;
        var progress = interactive ? new ProgressBar(console.Out, settings.Cycles) : null;
        var clock = Stopwatch.StartNew();
        var replay = options.Html is null ? null : new ReplayRecorder();
        using (var trace = options.Trace is null ? null : new TraceWriter(options.Trace))
        {
            using var loop = new MatchLoop(match, settings.Cycles, trace, replay);
            bool printLogs = options.StrategyLog && trace is null && replay is null;
            Action<int>? played = progress is null && !printLogs ? null : cycle =>
            {
                if (printLogs)
                {
                    PrintLogs(match, cycle, console);
                }

                progress?.Update(cycle);
            };
            loop.Play(played: played);
            trace?.Complete();
        }

        if (replay is not null)
        {
            AtomicFile.WriteAllText(options.Html!, ReplayPage.Replay(replay.ToJson()));
        }

        clock.Stop();
        progress?.Clear();
        if (options.Svg is not null)
        {
            var names = new string[match.TeamCount];
            for (int t = 0; t < names.Length; t++)
            {
                names[t] = match.TeamLabel(t);
            }

            SvgFrame.Write(match.World, match.Rules.Scores, options.Svg, names);
        }

        console.Out.Write(MatchSummary.Format(match, clock.Elapsed));
        Wrote(console, options.Trace, "the trace");
        Wrote(console, options.Svg, "the final frame");
        Wrote(console, options.Html, "the replay page");
        return ExitCodes.Success;
    }

    // --strategy-log without a file: what each strategy printed while deciding this cycle, on standard
    // error, each line as "cycle N, team T (NAME): TEXT".
    private static void PrintLogs(Match match, int cycle, CliConsole console)
    {
        foreach (var slot in match.Caller().Slots)
        {
            if (slot.Log is not { } log || (log.Length == 0 && log.Dropped == 0))
            {
                continue;
            }

            string text = log.ToString();
            string prefix = $"cycle {cycle}, team {slot.Team} ({slot.Label}): ";
            foreach (string line in text.EndsWith('\n') ? text[..^1].Split('\n') : text.Split('\n'))
            {
                console.ErrorLine(prefix + line); // escaped: what a strategy prints never reaches the terminal as control characters
            }
        }
    }

    /// <summary>The line that says a file was written: <c>wrote FILE (what)</c>; nothing when <paramref name="path"/> is null.</summary>
    internal static void Wrote(CliConsole console, string? path, string what)
    {
        if (path is not null)
        {
            console.Out.Write($"wrote {path} ({what})\n");
        }
    }

    /// <summary>The settings of the match the options ask for (the scene's cycles unless --cycles or --minutes).</summary>
    public static MatchSettings Settings(RunOptions options, ScenarioDefinition scenario, TeamStrategy?[] teams) =>
        new(scenario, options.CyclesFor(scenario), options.Seed, options.Noise, teams, options.StrategyTimeoutMs, options.Threads ?? 1, options.DebugDraw, options.StrategyLog, options.TimeBank);

    /// <summary>
    /// The strategies of the command line: with <c>--isolation process</c> (the default) readied for
    /// strategy hosts (sources compiled once per run; every match built from them starts fresh hosts),
    /// with <c>--isolation none</c> loaded in process (a fresh instance each call; a constructor that throws is
    /// the team's fault in cycle 1, not a load error). Built-in names run in process.
    /// </summary>
    /// <exception cref="StrategyLoadException">A strategy cannot be used, or <c>--sandbox required</c> cannot be met; the message starts with the option.</exception>
    /// <param name="options">The options.</param>
    /// <param name="console">Where the remote teams' lines go (null: no remote teams are made; <c>--batch</c> has none).</param>
    /// <param name="progress">Told a line when a team's sources start and finish compiling.</param>
    /// <param name="seats">The teams of an earlier match, whose remote teams are kept as they are (their seats stay bound), or null.</param>
    public static TeamStrategy?[] LoadTeams(RunOptions options, CliConsole? console = null, Action<string>? progress = null, IReadOnlyList<TeamStrategy?>? seats = null)
    {
        var teams = new TeamStrategy?[options.Strategies.Length];
        for (int t = 0; t < teams.Length; t++)
        {
            if (options.Strategies[t] is { } spec)
            {
                try
                {
                    teams[t] = options.RemotePorts[t] is int port && seats?[t] is { Remote: not null } kept ? kept
                        : options.RemotePorts[t] is int free && console is not null ? Remote(options, t, free, console)
                        : LoadTeam(options, spec, progress);
                }
                catch (StrategyLoadException e)
                {
                    if (seats is null)
                    {
                        foreach (var bound in teams)
                        {
                            bound?.Remote?.Dispose(); // a seat already bound is let go
                        }
                    }

                    throw new StrategyLoadException($"--strategy {t}: {e.Message}", e.Details);
                }
            }
        }

        return teams;
    }

    /// <summary>
    /// One team's strategy from its spec (not a remote one), as <see cref="LoadTeams"/> loads it:
    /// <c>demo</c>, a built-in name (in process), or a user strategy readied for strategy hosts
    /// (<c>--isolation process</c>) or loaded in process (<c>--isolation none</c>).
    /// </summary>
    /// <exception cref="StrategyLoadException">The strategy cannot be used, or <c>--sandbox required</c> cannot be met.</exception>
    /// <param name="options">The options (isolation, sandbox, hosts' settings).</param>
    /// <param name="spec">The spec.</param>
    /// <param name="progress">Told a line when the sources start and finish compiling.</param>
    public static TeamStrategy LoadTeam(RunOptions options, string spec, Action<string>? progress = null)
    {
        if (spec == TeamStrategy.DemoSpec)
        {
            return TeamStrategy.ItemDemo;
        }

        var prepared = options.Isolation == IsolationMode.Process ? StrategyResolver.Prepare(spec, progress, options.HostSettings) : null;
        if (prepared is not null)
        {
            bool sandbox = HostSandbox.Use(options.Sandbox); // the warning or the refusal, before the match
            HostPool.Reserve(prepared, options.HostSettings, sandbox); // its host starts now, while the match is set up
        }

        return prepared is null
            ? TeamStrategy.InProcess(TeamName.OfSpec(spec), spec, progress, options.HostSettings)
            : TeamStrategy.Hosted(TeamName.OfSpec(spec), prepared, options.HostSettings);
    }

    // A remote team's seat, bound now so that a port in use is an error before the match.
    private static TeamStrategy Remote(RunOptions options, int team, int port, CliConsole console)
    {
        if (!System.Net.IPAddress.IsLoopback(options.RemoteHost))
        {
            console.ErrorLine($"run: warning: --remote-host {options.RemoteHost} is not a loopback address: any machine that reaches it may connect{(options.RemoteTokens[team] is null ? " (give --remote-token)" : "")}");
        }

        var seat = new RemoteSeat(team, options.RemoteHost, port, options.RemoteTokens[team], TimeSpan.FromSeconds(options.RemoteWaitSeconds), console.ErrorLine);
        return TeamStrategy.RemoteClient(RunOptions.RemotePrefix + seat.EndPoint.Port.ToString(CultureInfo.InvariantCulture), seat);
    }

    // The scene and its name in result files: item SLUG (no scene option: ball-grab), default,
    // crowd N, or the file's name and SHA-256.
    private static (ScenarioDefinition Scenario, string Scene) LoadScene(RunOptions options, CliConsole console)
    {
        if (options.Crowd is int movers)
        {
            return (CrowdScenario.Create(movers), string.Create(CultureInfo.InvariantCulture, $"crowd {movers}"));
        }

        if (options.Item == "default")
        {
            return (DefaultScenario.Load(), "default");
        }

        if (options.Scenario is null)
        {
            var item = ItemRegistry.Find(options.Item ?? MainItem)!;
            return (item.CreateScenario(options.Seed ?? 1), "item " + item.Slug);
        }

        string text = ReadScenario(options.Scenario, console);
        string hash = Convert.ToHexStringLower(SHA256.HashData(Encoding.UTF8.GetBytes(text)));
        string name = options.Scenario == "-" ? "stdin" : Path.GetFileName(options.Scenario);
        return (ScenarioFile.Parse(text), $"file {name} sha256 {hash}");
    }

    private static string ReadScenario(string path, CliConsole console)
    {
        try
        {
            if (path != "-" && new FileInfo(path) is { Exists: true, Length: > InputLimits.InputBytes } info)
            {
                throw new ScenarioException(path, InputLimits.TooLarge(info.Length));
            }

            return path == "-" ? InputText.ReadLimited(console.In, path) : File.ReadAllText(path);
        }
        catch (InputException e)
        {
            throw new ScenarioException(path, e.Message);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new ScenarioException(path, $"cannot read the scenario file ({e.Message})");
        }
    }

    private static string HelpText() =>
        $"Usage: {CliApp.ProgramName} {RunOptions.Usage}\n\n" +
        "Plays a match of 100 ms cycles and prints the cycles played, simulated and wall time, the seed, the score and\n" +
        "the winner, contacts by pair kind, sub-steps, the largest leftover overlap and strategy faults.\n" +
        "--item NAME plays a competition item of the original with its rules (--list-items lists them; --minutes\n" +
        "10|5|3|1, default 10); without a scene option it plays ball-grab; --item default is the old default scene;\n" +
        "--crowd N generates a crowded scene of N fish and balls.\n" +
        "--strategy TEAM=SPEC gives a whole team a strategy: a built-in name (idle, chase-ball, demo: the item's own\n" +
        "demo), a .dll built against\n" +
        "either API (the SDK's or the original's), a .cs file or a folder of .cs files (compiled in process), each in\n" +
        "its own load context; --strategy-timeout is its deadline per call in ms of CPU time (default 100); a late call\n" +
        "is waited for and paid from the team's time bank (--time-bank SECONDS; default a tenth of the match's\n" +
        "deadlines, at least 5 s); a team whose bank is spent plays idle. --strategy TEAM=remote:PORT waits for a remote client to play the team over TCP (connect, or any client\n" +
        "of docs/protocol.md; PORT 0: any free one) for --remote-wait SECONDS (default 60), on 127.0.0.1 unless\n" +
        "--remote-host ADDR; --remote-token [TEAM=]TOKEN must be presented by the client (docs/cli.md, Remote teams).\n" +
        "--trace writes JSON Lines, --svg the final frame, --html a self-contained replay page (docs/viewer.md); an\n" +
        "existing trace, page or results file is replaced only with --force. --live serves the match in the browser at\n" +
        "http://127.0.0.1:8080/ as it is played (--port N, --host H, --speed X times real time, --paused to start paused);\n" +
        "--strategies DIR adds a control board to the page: choose the item, its length and each team's strategy (DIR's\n" +
        "folders, .cs and .dll files, or a built-in), start, recompile and restart, save the replay page and a PNG.\n" +
        "--debug-draw records the strategies' debug drawings (DebugDraw) in the trace and both pages; --strategy-log\n" +
        "records what they print (Console, Debug; at most 4,096 characters per team and cycle) there too, or, with\n" +
        "none of --trace, --html and --live, prints it to stderr line by line as 'cycle N, team T (NAME): TEXT'.\n" +
        "--threads P: a single match spreads each cycle's independent islands of bodies over P threads (default 1;\n" +
        "the same match whatever P); with --batch, P is the number of matches played at once (default: every core).\n" +
        "--batch N plays N matches with seeds S .. S+N-1 on every core (--threads P), one line each and an aggregate;\n" +
        "--shard I/K plays matches j with j mod K = I; --results FILE writes JSON Lines for 'merge'.\n" +
        "--slurm DIR writes the batch as a Slurm job array of --shards K tasks and a merge job (--partition, --time,\n" +
        "--sbatch-arg ARG for any other sbatch option, --slurm-setup FILE sourced by the jobs first, e.g. module loads);\n" +
        "--submit submits them; asked again, only the shards without results are played.\n" +
        "Formats: docs/items.md, docs/scenario.md, docs/simulation.md, docs/batch.md, docs/strategies.md.\n";
}
