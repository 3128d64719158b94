using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.Linq;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Messages;
using URWPGSim2D.Ladder;
using URWPGSim2D.Ladder.Web;
using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>ladder serve | create | list | pause | resume | team add | submit | final | worker</c>: the
/// competition ladder (docs/ladder.md). <c>serve</c> runs the service (<see cref="LadderServer"/>)
/// until stopped; <c>worker</c> plays its matches beside it; the others talk to a running one
/// (<see cref="LadderClient"/>), naming one of its ladders with <c>--ladder</c> when it runs several. Each sub-command's options are declared once, in its usage line.
/// </summary>
internal sealed class LadderCommand : ICliCommand
{
    private static readonly Option<bool> HelpOption = CliSyntax.Help();

    private static readonly Option<bool> ServeHelp = CliSyntax.Help();
    private static readonly Option<string> ItemOption = CliSyntax.Value("--item", "ITEM", "the item of the ladder to create or reopen (default: the newest ladder, else ball-grab)", CliCompletions.TournamentItems);
    private static readonly Option<string> MinutesOption = CliSyntax.Value("--minutes", "M", "length of its matches: 10, 5, 3 or 1 minutes (default 10 for a new ladder)");
    private static readonly Option<string> DataOption = CliSyntax.Value("--data", "DIR", "the data folder: database, submissions, replays (default ladder-data)", CliCompletions.Paths);
    private static readonly Option<string> DatabaseOption = CliSyntax.Value("--database", "CONNECTION", "a PostgreSQL connection string (default: SQLite in DIR)");
    private static readonly Option<string> PortOption = CliSyntax.Value("--port", "P", "the port to listen on (default 5080; 0: any free one)");
    private static readonly Option<string> HostOption = CliSyntax.Value("--host", "H", "the address to listen on (default 127.0.0.1, loopback only)");
    private static readonly Option<string> ServeAdminOption = CliSyntax.Value("--admin-token", "TOKEN", "the organiser's token (default: the stored one, or a new one printed on the first start)");
    private static readonly Option<string> WorkersOption = CliSyntax.Value("--workers", "N", "matches played at once (default 1; 0: none, another worker plays)");
    private static readonly Option<string> TakeoverOption = CliSyntax.Value("--takeover", "S", "with --database: seconds before a match of a worker that stopped answering is played by another (10 to 86400; default: as kept, else 60)");

    private static readonly UsageLine ServeLine = new(
        UsageLine.Optional(ItemOption), UsageLine.Optional(MinutesOption), UsageLine.Optional(DataOption), UsageLine.Optional(DatabaseOption),
        UsageLine.Optional(PortOption), UsageLine.Optional(HostOption), UsageLine.Optional(ServeAdminOption), UsageLine.Optional(WorkersOption),
        UsageLine.Optional(TakeoverOption));

    private static readonly Option<bool> AddHelp = CliSyntax.Help();
    private static readonly Option<string> AddServerOption = CliSyntax.Value("--server", "URL", "the ladder's address, e.g. http://127.0.0.1:5080/");
    private static readonly Option<string> AddAdminOption = CliSyntax.Value("--admin-token", "T", "the organiser's token");
    private static readonly Option<string> StrategyOption = CliSyntax.Value("--strategy", "demo|chase-ball|idle", "a house entrant playing this built-in strategy");

    private static readonly Option<string> AddLadderOption = CliSyntax.Value("--ladder", "L", "the ladder a house entrant plays in: its id, or its item (needed when the service runs several)");

    private static readonly UsageLine AddLine = new(
        CliSyntax.Positional("NAME", "the team's name"), AddServerOption, AddAdminOption, UsageLine.Optional(StrategyOption), UsageLine.Optional(AddLadderOption));

    private static readonly Option<bool> SubmitHelp = CliSyntax.Help();
    private static readonly Option<string> SubmitServerOption = CliSyntax.Value("--server", "URL", "the ladder's address, e.g. http://127.0.0.1:5080/");
    private static readonly Option<string> TokenOption = CliSyntax.Value("--token", "T", "the team's token");

    private static readonly Option<string> SubmitLadderOption = CliSyntax.Value("--ladder", "L", "the ladder: its id, or its item when one ladder plays it (needed when the service runs several)");

    private static readonly UsageLine SubmitLine = new(
        SubmitServerOption, TokenOption, UsageLine.Optional(SubmitLadderOption), CliSyntax.Positional("PATH", "a folder of .cs files, one .cs file or a DLL", CliCompletions.Paths));

    private static readonly Option<bool> FinalHelp = CliSyntax.Help();
    private static readonly Option<string> FinalServerOption = CliSyntax.Value("--server", "URL", "the ladder's address, e.g. http://127.0.0.1:5080/");
    private static readonly Option<string> FinalAdminOption = CliSyntax.Value("--admin-token", "T", "the organiser's token");
    private static readonly Option<string> TopOption = CliSyntax.Value("--top", "K", "how many of the highest-ranked teams play the final (2 or more)");
    private static readonly Option<string> RoundsOption = CliSyntax.Value("--rounds", "N", "matches of each pair (default 2)");

    private static readonly Option<string> FinalLadderOption = CliSyntax.Value("--ladder", "L", "the ladder: its id, or its item when one ladder plays it (needed when the service runs several)");

    private static readonly UsageLine FinalLine = new(FinalServerOption, FinalAdminOption, TopOption, UsageLine.Optional(RoundsOption), UsageLine.Optional(FinalLadderOption));

    private static readonly Option<bool> CreateHelp = CliSyntax.Help();
    private static readonly Option<string> CreateServerOption = CliSyntax.Value("--server", "URL", "the service's address, e.g. http://127.0.0.1:5080/");
    private static readonly Option<string> CreateAdminOption = CliSyntax.Value("--admin-token", "T", "the organiser's token");
    private static readonly Option<string> CreateItemOption = CliSyntax.Value("--item", "ITEM", "the item the ladder plays (an item of two teams)", CliCompletions.TournamentItems);
    private static readonly Option<string> CreateMinutesOption = CliSyntax.Value("--minutes", "M", "length of its matches: 10, 5, 3 or 1 minutes (default 10)");
    private static readonly Option<string> FirstSeedOption = CliSyntax.Value("--first-seed", "S", "match N plays seed S + N (default 1)");

    private static readonly UsageLine CreateLine = new(CreateServerOption, CreateAdminOption, CreateItemOption, UsageLine.Optional(CreateMinutesOption), UsageLine.Optional(FirstSeedOption));

    private static readonly Option<bool> ListHelp = CliSyntax.Help();
    private static readonly Option<string> ListServerOption = CliSyntax.Value("--server", "URL", "the service's address, e.g. http://127.0.0.1:5080/");

    private static readonly UsageLine ListLine = new(ListServerOption);

    private static readonly Option<bool> PauseHelp = CliSyntax.Help();
    private static readonly Option<string> PauseServerOption = CliSyntax.Value("--server", "URL", "the service's address, e.g. http://127.0.0.1:5080/");
    private static readonly Option<string> PauseAdminOption = CliSyntax.Value("--admin-token", "T", "the organiser's token");
    private static readonly Option<string> PauseLadderOption = CliSyntax.Value("--ladder", "L", "the ladder: its id, or its item when one ladder plays it (needed when the service runs several)");

    private static readonly UsageLine PauseLine = new(PauseServerOption, PauseAdminOption, UsageLine.Optional(PauseLadderOption));

    private static readonly Option<bool> ResumeHelp = CliSyntax.Help();
    private static readonly Option<string> ResumeServerOption = CliSyntax.Value("--server", "URL", "the service's address, e.g. http://127.0.0.1:5080/");
    private static readonly Option<string> ResumeAdminOption = CliSyntax.Value("--admin-token", "T", "the organiser's token");
    private static readonly Option<string> ResumeLadderOption = CliSyntax.Value("--ladder", "L", "the ladder: its id, or its item when one ladder plays it (needed when the service runs several)");

    private static readonly UsageLine ResumeLine = new(ResumeServerOption, ResumeAdminOption, UsageLine.Optional(ResumeLadderOption));

    private static readonly Command Serve = CliSyntax.Command("serve", "Run the ladder service.", ServeLine, ServeHelp);
    private static readonly Command Add = CliSyntax.Command("add", "Add a team to a running ladder.", AddLine, AddHelp);
    private static readonly Command Team = TeamCommand();
    private static readonly Command Submit = CliSyntax.Command("submit", "Submit a team's strategy to a running ladder.", SubmitLine, SubmitHelp);
    private static readonly Command Final = CliSyntax.Command("final", "Start a running ladder's final round.", FinalLine, FinalHelp);
    private static readonly Command Create = CliSyntax.Command("create", "Create a ladder in a running service.", CreateLine, CreateHelp);
    private static readonly Command List = CliSyntax.Command("list", "List a running service's ladders.", ListLine, ListHelp);
    private static readonly Command Pause = CliSyntax.Command("pause", "Pause a ladder's ranked play.", PauseLine, PauseHelp);
    private static readonly Command Resume = CliSyntax.Command("resume", "Resume a ladder's ranked play.", ResumeLine, ResumeHelp);

    private static readonly Option<bool> WorkerHelp = CliSyntax.Help();
    private static readonly Option<string> WorkerDatabaseOption = CliSyntax.Value("--database", "CONNECTION", "the service's PostgreSQL connection string");
    private static readonly Option<string> WorkerDataOption = CliSyntax.Value("--data", "DIR", "this worker's folder: copies of submissions, replays being played (default ladder-data; need not be the service's)", CliCompletions.Paths);
    private static readonly Option<string> WorkerWorkersOption = CliSyntax.Value("--workers", "N", "matches played at once (default 1)");

    private static readonly UsageLine WorkerLine = new(WorkerDatabaseOption, UsageLine.Optional(WorkerDataOption), UsageLine.Optional(WorkerWorkersOption));

    private static readonly Command Worker = CliSyntax.Command("worker", "Play a ladder's matches beside its service (PostgreSQL).", WorkerLine, WorkerHelp);

    /// <summary>The usage of <c>ladder serve</c>.</summary>
    public static string ServeUsage => "ladder serve " + ServeLine.Text;

    /// <summary>The usage of <c>ladder team add</c>.</summary>
    public static string AddUsage => "ladder team add " + AddLine.Text;

    /// <summary>The usage of <c>ladder submit</c>.</summary>
    public static string SubmitUsage => "ladder submit " + SubmitLine.Text;

    /// <summary>The usage of <c>ladder final</c>.</summary>
    public static string FinalUsage => "ladder final " + FinalLine.Text;

    /// <summary>The usage of <c>ladder create</c>.</summary>
    public static string CreateUsage => "ladder create " + CreateLine.Text;

    /// <summary>The usage of <c>ladder list</c>.</summary>
    public static string ListUsage => "ladder list " + ListLine.Text;

    /// <summary>The usage of <c>ladder pause</c>.</summary>
    public static string PauseUsage => "ladder pause " + PauseLine.Text;

    /// <summary>The usage of <c>ladder resume</c>.</summary>
    public static string ResumeUsage => "ladder resume " + ResumeLine.Text;

    /// <summary>The usage of <c>ladder worker</c>.</summary>
    public static string WorkerUsage => "ladder worker " + WorkerLine.Text;

    /// <inheritdoc/>
    public string Name => "ladder";

    /// <inheritdoc/>
    public string Synopsis => "ladder serve|create|list|pause|resume|team add|submit|final|worker ...";

    /// <inheritdoc/>
    public string Summary => "Run a competition ladder: teams upload strategies, ranked matches play without end, standings update live.";

    /// <inheritdoc/>
    public Command Syntax { get; } = LadderSyntax();

    private static Command TeamCommand()
    {
        var team = new Command("team", "Manage a running ladder's teams.");
        team.Subcommands.Add(Add);
        return team;
    }

    private static Command LadderSyntax()
    {
        var ladder = CliSyntax.Command("ladder", "Run a competition ladder.", HelpOption);
        ladder.Subcommands.Add(Serve);
        ladder.Subcommands.Add(Create);
        ladder.Subcommands.Add(List);
        ladder.Subcommands.Add(Pause);
        ladder.Subcommands.Add(Resume);
        ladder.Subcommands.Add(Team);
        ladder.Subcommands.Add(Submit);
        ladder.Subcommands.Add(Final);
        ladder.Subcommands.Add(Worker);
        return ladder;
    }

    /// <summary>The sub-command a parse chose: serve, add, submit, or null for <c>ladder</c> (or <c>ladder team</c>) alone.</summary>
    private static Command? Chosen(IReadOnlyList<CommandLineWord> words)
    {
        var positional = words.TakeWhile(w => w.Option is null && !w.Text.StartsWith('-')).Select(w => w.Text).ToList();
        return positional switch
        {
            ["serve", ..] => Serve,
            ["team", "add", ..] => Add,
            ["submit", ..] => Submit,
            ["final", ..] => Final,
            ["worker", ..] => Worker,
            ["create", ..] => Create,
            ["list", ..] => List,
            ["pause", ..] => Pause,
            ["resume", ..] => Resume,
            _ => null,
        };
    }

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        var chosen = Chosen(words);
        var rest = chosen == Add ? words.Skip(2).ToList() : chosen is null ? [.. words] : words.Skip(1).ToList();
        if (chosen is null)
        {
            if (rest.Count > 0 && rest[0].Option == HelpOption)
            {
                console.Out.Write(Help());
                return ExitCodes.Success;
            }

            if (rest.Count > 0 && rest[0].Text.StartsWith("--", StringComparison.Ordinal))
            {
                throw CliUsageException.UnknownOption("ladder", rest[0].Text, Syntax, CliApp.ProgramName + " " + Synopsis);
            }

            throw new CliUsageException(rest.Count == 0 ? "ladder: a sub-command is needed (serve, create, list, pause, resume, team add, submit, final, worker)" : $"ladder: unknown sub-command {MessageText.Quote(rest[0].Text)}", CliApp.ProgramName + " " + Synopsis);
        }

        if (chosen == Serve)
        {
            return RunServe(rest, console);
        }

        if (chosen == Final)
        {
            return RunFinal(rest, console);
        }

        if (chosen == Worker)
        {
            return RunWorker(rest, console);
        }

        if (chosen == Create)
        {
            return RunCreate(rest, console);
        }

        if (chosen == List)
        {
            return RunList(rest, console);
        }

        if (chosen == Pause || chosen == Resume)
        {
            return RunPause(rest, console, chosen == Pause);
        }

        return chosen == Add ? RunAdd(rest, console) : RunSubmit(rest, console);
    }

    private static string Help() =>
        $"Usage: {CliApp.ProgramName} ladder serve|create|list|pause|resume|team add|submit|final|worker ...\n" +
        $"  {CliApp.ProgramName} {ServeUsage}\n" +
        $"  {CliApp.ProgramName} {CreateUsage}\n" +
        $"  {CliApp.ProgramName} {ListUsage}\n" +
        $"  {CliApp.ProgramName} {PauseUsage}\n" +
        $"  {CliApp.ProgramName} {ResumeUsage}\n" +
        $"  {CliApp.ProgramName} {AddUsage}\n" +
        $"  {CliApp.ProgramName} {SubmitUsage}\n" +
        $"  {CliApp.ProgramName} {FinalUsage}\n" +
        $"  {CliApp.ProgramName} {WorkerUsage}\n\n" +
        "serve runs the ladder service until stopped (Ctrl+C): pages and JSON API, and workers that play ranked\n" +
        "matches without end. create adds a ladder (one item) to a running service; list shows its ladders; pause and\n" +
        "resume stop and restart a ladder's ranked play. team add adds a team and prints its token alone on the last\n" +
        "line. submit uploads a team's strategy for a ladder, which is compiled and checked once; its newest working\n" +
        "submission plays. final starts a ladder's final round: every pair of the top K plays N matches, ranked play\n" +
        "stops, the standings become the final's. With several ladders, --ladder names the one meant.\n" +
        "worker plays matches of a service whose database is PostgreSQL, beside it, until stopped (Ctrl+C).\n" +
        "More: docs/ladder.md.\n";

    // The value options of one sub-command, each at most once; positional words apart.
    private static (Dictionary<Option, string> Values, List<string> Positional) Words(IReadOnlyList<CommandLineWord> words, string name, Command syntax, string usage, Option<bool> help, out bool helpAsked)
    {
        var values = new Dictionary<Option, string>();
        var positional = new List<string>();
        helpAsked = false;
        foreach (var word in words)
        {
            if (word.Option == help)
            {
                helpAsked = true;
            }
            else if (word.Option is { } option)
            {
                string value = word.Value ?? throw new CliUsageException($"{name}: {option.Name} needs a value", usage);
                if (!values.TryAdd(option, value))
                {
                    throw new CliUsageException($"{name}: {option.Name} given twice", usage);
                }
            }
            else if (word.Text.StartsWith("--", StringComparison.Ordinal))
            {
                throw CliUsageException.UnknownOption(name, word.Text, syntax, usage);
            }
            else
            {
                positional.Add(word.Text);
            }
        }

        return (values, positional);
    }

    private static int RunServe(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        string usage = CliApp.ProgramName + " " + ServeUsage;
        var (values, positional) = Words(words, "ladder serve", Serve, usage, ServeHelp, out bool help);
        if (help)
        {
            WriteHelp(console, usage, "Runs the ladder service until stopped (Ctrl+C).", ServeLine.OptionTable(24));
            return ExitCodes.Success;
        }

        RefuseArguments("ladder serve", positional, usage);

        var settings = new LadderSettings();
        if (values.TryGetValue(ItemOption, out string? item))
        {
            settings = settings with { Item = ItemRegistry.Find(item)?.Slug ?? throw ItemList.Unknown("ladder serve", item, withDefault: false) };
        }

        if (values.TryGetValue(MinutesOption, out string? minutes))
        {
            settings = settings with { Cycles = Cycles("ladder serve", minutes) };
        }

        if (values.TryGetValue(DataOption, out string? data))
        {
            settings = settings with { DataDir = data.Length > 0 ? data : throw new CliUsageException("ladder serve: --data needs a folder, got \"\"", null) };
        }

        if (values.TryGetValue(DatabaseOption, out string? database))
        {
            settings = settings with { Database = database.Length > 0 ? database : throw new CliUsageException("ladder serve: --database needs a connection string, got \"\"", null) };
        }

        if (values.TryGetValue(PortOption, out string? port))
        {
            settings = settings with { Port = Number("--port", port, 0, 65535) };
        }

        if (values.TryGetValue(HostOption, out string? host))
        {
            settings = settings with { Host = host };
        }

        if (values.TryGetValue(ServeAdminOption, out string? admin))
        {
            settings = settings with { AdminToken = admin.Length >= 8 ? admin : throw new CliUsageException($"ladder serve: --admin-token must be at least 8 characters, got {admin.Length}", null) };
        }

        if (values.TryGetValue(WorkersOption, out string? workers))
        {
            settings = settings with { Workers = Number("--workers", workers, 0, 256) };
        }

        if (values.TryGetValue(TakeoverOption, out string? takeover))
        {
            settings = settings with { Takeover = TimeSpan.FromSeconds(Number("--takeover", takeover, LadderSettings.MinTakeoverSeconds, LadderSettings.MaxTakeoverSeconds)) };
        }

        return Serving(settings, console);
    }

    private static int Serving(LadderSettings settings, CliConsole console)
    {
        LadderServer server;
        try
        {
            server = LadderServer.StartAsync(settings, line => console.ErrorLine(line)).GetAwaiter().GetResult();
        }
        catch (LadderInputException e)
        {
            console.ErrorLine("ladder serve: " + e.Message);
            return ExitCodes.BadInput;
        }
        catch (System.IO.IOException e)
        {
            console.ErrorLine("ladder serve: " + e.Message.ReplaceLineEndings(" "));
            return ExitCodes.BadInput;
        }

        try
        {
            var ladders = server.Ladders;
            string items = ladders.Count == 1 ? "ladder: " + ladders[0].Item : "ladders: " + string.Join(", ", ladders.Select(l => string.Create(CultureInfo.InvariantCulture, $"{l.Id} {l.Item}")));
            console.Out.WriteLine($"{items} at {server.Url} (data: {settings.DataDir}, {(settings.Database is null ? "SQLite" : "PostgreSQL")}); Ctrl+C stops it");
            if (server.NewAdminToken is { } token)
            {
                console.Out.WriteLine("organiser token (shown once; keep it):");
                console.Out.WriteLine(token);
            }

            console.Out.Flush();
            server.WaitForShutdownAsync().GetAwaiter().GetResult();
        }
        finally
        {
            server.DisposeAsync().AsTask().GetAwaiter().GetResult();
        }

        return ExitCodes.Success;
    }

    private static int RunAdd(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        string usage = CliApp.ProgramName + " " + AddUsage;
        var (values, positional) = Words(words, "ladder team add", Add, usage, AddHelp, out bool help);
        if (help)
        {
            WriteHelp(console, usage, "Adds a team to a running ladder and prints its token alone on the last line.", AddLine.OptionTable(28));
            return ExitCodes.Success;
        }

        if (positional.Count != 1)
        {
            throw new CliUsageException(positional.Count == 0 ? "ladder team add: NAME is required" : $"ladder team add: unexpected argument {MessageText.Quote(positional[1])} (one NAME)", usage);
        }

        string server = values.GetValueOrDefault(AddServerOption) ?? throw new CliUsageException("ladder team add: --server URL is required", usage);
        string admin = values.GetValueOrDefault(AddAdminOption) ?? throw new CliUsageException("ladder team add: --admin-token T is required", usage);
        string? strategy = values.GetValueOrDefault(StrategyOption);
        if (strategy is not null && !LadderSettings.HouseStrategies.Contains(strategy))
        {
            throw new CliUsageException($"ladder team add: --strategy must be demo, chase-ball or idle, got {MessageText.Quote(strategy)}", null);
        }

        string? ladder = values.GetValueOrDefault(AddLadderOption);
        if (ladder is not null && strategy is null)
        {
            throw new CliUsageException("ladder team add: --ladder names the ladder of a house entrant (--strategy); a team that submits plays in every ladder it submits to", null);
        }

        return Ask("ladder team add", server, admin, ladder, console, client =>
        {
            var (name, token) = client.AddTeamAsync(positional[0], strategy).GetAwaiter().GetResult();
            console.Out.WriteLine(strategy is null ? $"team {name} added; its token (shown once):" : $"team {name} added, a house entrant playing {strategy}; its token (shown once):");
            console.Out.WriteLine(token);
            return ExitCodes.Success;
        });
    }

    // One request to a running ladder: its refusal (or an unreachable service) is one line on standard error and exit 2.
    private static int Ask(string command, string server, string token, string? ladder, CliConsole console, Func<LadderClient, int> ask)
    {
        try
        {
            using var client = new LadderClient(server, token, ladder);
            return ask(client);
        }
        catch (LadderInputException e)
        {
            console.ErrorLine(command + ": " + e.Message);
            return ExitCodes.BadInput;
        }
    }

    private static int RunSubmit(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        string usage = CliApp.ProgramName + " " + SubmitUsage;
        var (values, positional) = Words(words, "ladder submit", Submit, usage, SubmitHelp, out bool help);
        if (help)
        {
            WriteHelp(console, usage, "Uploads a team's strategy: a folder of .cs files, one .cs file or a DLL (also one built for the original).\n" +
                "It is compiled and checked once; the compile errors are printed as run prints them (exit 2).", SubmitLine.OptionTable(14));
            return ExitCodes.Success;
        }

        if (positional.Count != 1)
        {
            throw new CliUsageException(positional.Count == 0 ? "ladder submit: PATH is required" : $"ladder submit: unexpected argument {MessageText.Quote(positional[1])} (one PATH)", usage);
        }

        string server = values.GetValueOrDefault(SubmitServerOption) ?? throw new CliUsageException("ladder submit: --server URL is required", usage);
        string token = values.GetValueOrDefault(TokenOption) ?? throw new CliUsageException("ladder submit: --token T is required", usage);
        return Ask("ladder submit", server, token, values.GetValueOrDefault(SubmitLadderOption), console, client =>
        {
            var (id, ok, log) = client.SubmitAsync(positional[0]).GetAwaiter().GetResult();
            if (!ok)
            {
                foreach (string line in log.Split('\n'))
                {
                    console.ErrorLine(line);
                }

                return ExitCodes.BadInput;
            }

            console.Out.WriteLine(string.Create(CultureInfo.InvariantCulture, $"submission {id}: ok"));
            console.Out.WriteLine(log);
            return ExitCodes.Success;
        });
    }

    private static int RunWorker(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        string usage = CliApp.ProgramName + " " + WorkerUsage;
        var (values, positional) = Words(words, "ladder worker", Worker, usage, WorkerHelp, out bool help);
        if (help)
        {
            WriteHelp(console, usage, "Plays the matches a ladder service queues in its PostgreSQL database, beside it, until stopped (Ctrl+C).\n" +
                "It needs only the database: submissions and match outputs go through it; DIR keeps this worker's copies.", WorkerLine.OptionTable(24));
            return ExitCodes.Success;
        }

        RefuseArguments("ladder worker", positional, usage);

        string database = values.GetValueOrDefault(WorkerDatabaseOption) ?? throw new CliUsageException("ladder worker: --database CONNECTION is required", usage);
        var settings = new LadderSettings { Database = database.Length > 0 ? database : throw new CliUsageException("ladder worker: --database needs a connection string, got \"\"", null) };
        if (values.TryGetValue(WorkerDataOption, out string? data))
        {
            settings = settings with { DataDir = data.Length > 0 ? data : throw new CliUsageException("ladder worker: --data needs a folder, got \"\"", null) };
        }

        if (values.TryGetValue(WorkerWorkersOption, out string? workers))
        {
            settings = settings with { Workers = Number("ladder worker", "--workers", workers, 1, 256) };
        }

        var gate = new object();
        void Told(long match, bool done)
        {
            lock (gate)
            {
                console.Out.WriteLine(done ? $"ladder worker: match {match} played" : $"ladder worker: playing match {match}");
                console.Out.Flush();
            }
        }

        // Its first line before any match's: the matches' lines wait for the lock.
        LadderWorker worker;
        lock (gate)
        {
            try
            {
                worker = LadderWorker.Start(settings, Told);
            }
            catch (LadderInputException e)
            {
                console.ErrorLine("ladder worker: " + e.Message);
                return ExitCodes.BadInput;
            }

            console.Out.WriteLine($"ladder worker: {settings.Workers} match(es) at once (data: {settings.DataDir}, PostgreSQL); Ctrl+C stops it");
            console.Out.Flush();
        }

        using var stop = new System.Threading.ManualResetEventSlim();
        void Stop(System.Runtime.InteropServices.PosixSignalContext context)
        {
            context.Cancel = true;
            stop.Set();
        }

        using (System.Runtime.InteropServices.PosixSignalRegistration.Create(System.Runtime.InteropServices.PosixSignal.SIGINT, Stop))
        using (System.Runtime.InteropServices.PosixSignalRegistration.Create(System.Runtime.InteropServices.PosixSignal.SIGTERM, Stop))
        {
            stop.Wait();
            worker.Dispose();
        }

        return ExitCodes.Success;
    }

    private static int RunFinal(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        string usage = CliApp.ProgramName + " " + FinalUsage;
        var (values, positional) = Words(words, "ladder final", Final, usage, FinalHelp, out bool help);
        if (help)
        {
            WriteHelp(console, usage, "Starts the final round: every pair of the top K teams plays N matches (sides alternate), ranked play\n" +
                "stops and the standings become those of the final's matches.", FinalLine.OptionTable(20));
            return ExitCodes.Success;
        }

        RefuseArguments("ladder final", positional, usage);

        string server = values.GetValueOrDefault(FinalServerOption) ?? throw new CliUsageException("ladder final: --server URL is required", usage);
        string admin = values.GetValueOrDefault(FinalAdminOption) ?? throw new CliUsageException("ladder final: --admin-token T is required", usage);
        string top = values.GetValueOrDefault(TopOption) ?? throw new CliUsageException("ladder final: --top K is required", usage);
        int k = Number("ladder final", "--top", top, 2, 1000);
        int rounds = values.TryGetValue(RoundsOption, out string? r) ? Number("ladder final", "--rounds", r, 1, 100) : 2;
        return Ask("ladder final", server, admin, values.GetValueOrDefault(FinalLadderOption), console, client =>
        {
            var (teams, matches) = client.StartFinalAsync(k, rounds).GetAwaiter().GetResult();
            console.Out.WriteLine(string.Create(CultureInfo.InvariantCulture, $"final round started: {string.Join(", ", teams)}; each pair plays {rounds} {(rounds == 1 ? "match" : "matches")}, {matches} in all"));
            return ExitCodes.Success;
        });
    }

    // The option values of a sub-command that takes no argument, or null when --help was asked (and answered).
    private static Dictionary<Option, string>? Options(IReadOnlyList<CommandLineWord> words, CliConsole console, Command command, UsageLine line, Option<bool> helpOption, string about, out string usage)
    {
        string name = "ladder " + command.Name;
        usage = CliApp.ProgramName + " " + name + " " + line.Text;
        var (values, positional) = Words(words, name, command, usage, helpOption, out bool help);
        if (help)
        {
            WriteHelp(console, usage, about, line.OptionTable(22));
            return null;
        }

        RefuseArguments(name, positional, usage);
        return values;
    }

    private static int RunCreate(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (Options(words, console, Create, CreateLine, CreateHelp, "Creates a ladder in a running service: the item it plays, the length of its matches, its first seed.", out string usage) is not { } values)
        {
            return ExitCodes.Success;
        }

        string server = values.GetValueOrDefault(CreateServerOption) ?? throw new CliUsageException("ladder create: --server URL is required", usage);
        string admin = values.GetValueOrDefault(CreateAdminOption) ?? throw new CliUsageException("ladder create: --admin-token T is required", usage);
        string itemText = values.GetValueOrDefault(CreateItemOption) ?? throw new CliUsageException("ladder create: --item ITEM is required", usage);
        string item = ItemRegistry.Find(itemText)?.Slug ?? throw ItemList.Unknown("ladder create", itemText, withDefault: false);
        int cycles = values.TryGetValue(CreateMinutesOption, out string? minutes) ? Cycles("ladder create", minutes) : 6000;
        ulong firstSeed = 1;
        if (values.TryGetValue(FirstSeedOption, out string? seed) && !ulong.TryParse(seed, NumberStyles.None, CultureInfo.InvariantCulture, out firstSeed))
        {
            throw new CliUsageException($"ladder create: --first-seed must be a whole number from 0 to {ulong.MaxValue}, got {MessageText.Quote(seed)}", null);
        }

        return Ask("ladder create", server, admin, null, console, client =>
        {
            var l = client.CreateLadderAsync(item, cycles, firstSeed).GetAwaiter().GetResult();
            console.Out.WriteLine(string.Create(CultureInfo.InvariantCulture, $"ladder {l.Id} created: {l.Item}, {l.Cycles} cycles a match, first seed {l.FirstSeed}"));
            return ExitCodes.Success;
        });
    }

    private static int RunList(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (Options(words, console, List, ListLine, ListHelp, "Lists a running service's ladders, one a line.", out string usage) is not { } values)
        {
            return ExitCodes.Success;
        }

        string server = values.GetValueOrDefault(ListServerOption) ?? throw new CliUsageException("ladder list: --server URL is required", usage);
        return Ask("ladder list", server, string.Empty, null, console, client =>
        {
            foreach (var l in client.LaddersAsync().GetAwaiter().GetResult())
            {
                console.Out.WriteLine(Line(l) + string.Create(CultureInfo.InvariantCulture, $"; {l.Teams} {(l.Teams == 1 ? "team" : "teams")}, {l.Matches} {(l.Matches == 1 ? "match" : "matches")}") + (l.Leader is { } leader ? ", first " + leader : string.Empty));
            }

            return ExitCodes.Success;
        });
    }

    private static int RunPause(IReadOnlyList<CommandLineWord> words, CliConsole console, bool pause)
    {
        string name = pause ? "ladder pause" : "ladder resume";
        if (Options(words, console, pause ? Pause : Resume, pause ? PauseLine : ResumeLine, pause ? PauseHelp : ResumeHelp,
            pause ? "Pauses a ladder's ranked play (matches already running finish)." : "Resumes a ladder's ranked play.", out string usage) is not { } values)
        {
            return ExitCodes.Success;
        }

        string server = values.GetValueOrDefault(pause ? PauseServerOption : ResumeServerOption) ?? throw new CliUsageException(name + ": --server URL is required", usage);
        string admin = values.GetValueOrDefault(pause ? PauseAdminOption : ResumeAdminOption) ?? throw new CliUsageException(name + ": --admin-token T is required", usage);
        return Ask(name, server, admin, values.GetValueOrDefault(pause ? PauseLadderOption : ResumeLadderOption), console, client =>
        {
            console.Out.WriteLine(Line(client.SetPausedAsync(pause).GetAwaiter().GetResult()));
            return ExitCodes.Success;
        });
    }

    // "ladder 2: polo-1v1, 600 cycles a match, playing" (paused, or final round).
    private static string Line(LadderSummary l) =>
        string.Create(CultureInfo.InvariantCulture, $"ladder {l.Id}: {l.Item}, {l.Cycles} cycles a match, {(l.Final ? "final round" : l.Paused ? "paused" : "playing")}");

    // --minutes: 10, 5, 3 or 1; its cycles.
    private static int Cycles(string command, string minutes) => minutes switch
    {
        "10" => 6000,
        "5" => 3000,
        "3" => 1800,
        "1" => 600,
        _ => throw new CliUsageException($"{command}: --minutes must be 10, 5, 3 or 1, got {MessageText.Quote(minutes)}", null),
    };

    private static int Number(string name, string value, int low, int high) => Number("ladder serve", name, value, low, high);

    private static int Number(string command, string name, string value, int low, int high) =>
        int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n >= low && n <= high ? n
        : throw new CliUsageException(string.Create(CultureInfo.InvariantCulture, $"{command}: {name} must be a whole number from {low} to {high}, got {MessageText.Quote(value)}"), null);

    // A subcommand's --help: its usage, what it does, its options.
    private static void WriteHelp(CliConsole console, string usage, string about, string options) =>
        console.Out.Write($"Usage: {usage}\n\n{about} Options:\n{options}More: docs/ladder.md.\n");

    // A subcommand that takes no argument refuses the first one given.
    private static void RefuseArguments(string command, IReadOnlyList<string> positional, string usage)
    {
        if (positional.Count > 0)
        {
            throw new CliUsageException($"{command}: unexpected argument {MessageText.Quote(positional[0])}", usage);
        }
    }
}
