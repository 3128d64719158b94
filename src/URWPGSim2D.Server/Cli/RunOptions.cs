using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;

namespace URWPGSim2D.Server.Cli;

/// <summary>The parsed arguments of <c>run</c>.</summary>
internal sealed class RunOptions
{
    /// <summary>The command's synopsis in the program's help.</summary>
    public const string Synopsis = "run [--item NAME | --scenario FILE] [options]";

    /// <summary>The command's full usage (<see cref="RunSyntax.Usage"/>).</summary>
    public static string Usage { get; } = "run " + RunSyntax.Usage.Text;

    /// <summary>Every long option of <c>run</c>, as declared (<see cref="RunSyntax"/>).</summary>
    public static IReadOnlyList<string> KnownOptions { get; } = CliSyntax.LongNames(RunSyntax.Command);

    /// <summary>Largest batch.</summary>
    public const int MaximumBatch = 100_000_000;

    /// <summary>Whether an existing --trace, --html or --results file may be replaced (<c>--force</c>).</summary>
    public bool Force { get; private set; }

    /// <summary>Competition item slug or Chinese name (<c>--item NAME</c>; "default" is the old default scene), or null.</summary>
    public string? Item { get; private set; }

    /// <summary>Match length in minutes (<c>--minutes 10|5|3|1</c>), or null.</summary>
    public int? Minutes { get; private set; }

    /// <summary>Whether <c>--list-items</c> was given.</summary>
    public bool ListItems { get; private set; }

    /// <summary>Scenario file, or null for the embedded default match.</summary>
    public string? Scenario { get; private set; }

    /// <summary>Fish and balls of a generated crowd scene (<c>--crowd N</c>), or null.</summary>
    public int? Crowd { get; private set; }

    /// <summary>Number of matches of a batch (<c>--batch N</c>), or null for a single match.</summary>
    public int? Batch { get; private set; }

    /// <summary>This process's shard of the batch: index 0 … count − 1.</summary>
    public int ShardIndex { get; private set; }

    /// <summary>How many shards the batch is split into (1: the whole batch here).</summary>
    public int ShardCount { get; private set; } = 1;

    /// <summary>
    /// <c>--threads P</c>: with <c>--batch</c>, matches played at once (default: every core); for a
    /// single match, threads its motion world spreads each cycle's islands over (default 1).
    /// </summary>
    public int? Threads { get; private set; }

    /// <summary>JSON Lines result file of a batch, or null.</summary>
    public string? Results { get; private set; }

    /// <summary>Cycle count override.</summary>
    public int? Cycles { get; private set; }

    /// <summary>Seed override.</summary>
    public ulong? Seed { get; private set; }

    /// <summary>Noise override.</summary>
    public bool? Noise { get; private set; }

    /// <summary>Trace output file.</summary>
    public string? Trace { get; private set; }

    /// <summary>SVG output file.</summary>
    public string? Svg { get; private set; }

    /// <summary>Replay page output file (<c>--html FILE</c>), or null.</summary>
    public string? Html { get; private set; }

    /// <summary>Whether to serve the match live in the browser (<c>--live</c>).</summary>
    public bool Live { get; private set; }

    /// <summary>Port of the live view (<c>--port N</c>).</summary>
    public int Port { get; private set; } = DefaultPort;

    /// <summary>Address the live view listens on (<c>--host H</c>; loopback by default).</summary>
    public string Host { get; private set; } = "127.0.0.1";

    /// <summary>Live playing speed, multiple of real time (<c>--speed X</c>; 1 = 100 ms a cycle).</summary>
    public double Speed { get; private set; } = 1;

    /// <summary>Whether the live match waits for resume or step before its first cycle (<c>--paused</c>).</summary>
    public bool Paused { get; private set; }

    /// <summary>The folder whose strategies the live view's control board offers (<c>--strategies DIR</c>), or null for a live view without a board.</summary>
    public string? StrategiesFolder { get; private set; }

    /// <summary>Whether the strategies' debug drawings are recorded in the trace, the replay page and the live view (<c>--debug-draw</c>).</summary>
    public bool DebugDraw { get; private set; }

    /// <summary>
    /// Whether what the strategies print is recorded per team and cycle (<c>--strategy-log</c>): in the
    /// trace, the replay page and the live view, or, without any of them, printed to standard error
    /// with its cycle and team.
    /// </summary>
    public bool StrategyLog { get; private set; }

    /// <summary>Default port of the live view.</summary>
    public const int DefaultPort = 8080;

    /// <summary>Per team (0 to 3: teams 2 and 3 play only in four-team scenes), a strategy spec (built-in name, .dll, .cs file or folder) or null.</summary>
    public string?[] Strategies { get; } = new string?[4];

    /// <summary>Per team (0 to 3), the port of a remote team (<c>--strategy TEAM=remote:PORT</c>; 0: any free one), or null.</summary>
    public int?[] RemotePorts { get; } = new int?[4];

    /// <summary>Per team (0 to 3), the token its remote client must present (<c>--remote-token</c>), or null.</summary>
    public string?[] RemoteTokens { get; } = new string?[4];

    /// <summary>Each team's time bank for late calls (<c>--time-bank SECONDS</c>), or null for the default: a tenth of the match's deadlines, at least 5 s.</summary>
    public System.TimeSpan? TimeBank { get; private set; }

    /// <summary>How long a match waits for its remote clients (<c>--remote-wait SECONDS</c>; default 60).</summary>
    public int RemoteWaitSeconds { get; private set; } = RemoteSeat.DefaultWaitSeconds;

    /// <summary>The address remote teams listen on (<c>--remote-host ADDR</c>; loopback by default).</summary>
    public System.Net.IPAddress RemoteHost { get; private set; } = System.Net.IPAddress.Loopback;

    /// <summary>Where user strategies run (<c>--isolation process|none</c>; default process).</summary>
    public IsolationMode Isolation => HostSettings.Isolation;

    /// <summary>Whether strategy hosts run in the sandbox (<c>--sandbox auto|required|off</c>; default auto).</summary>
    public SandboxMode Sandbox => HostSettings.Sandbox;

    /// <summary>GC heap limit of a strategy host, MiB (<c>--strategy-memory MB</c>; default 1024).</summary>
    public int StrategyMemoryMb => HostSettings.MemoryMb;

    /// <summary>The strategy hosts' settings (<see cref="HostOptions"/>).</summary>
    public HostSettings HostSettings { get; private set; } = HostSettings.Default;

    /// <summary>Deadline of a loaded strategy per call, ms of its thread's CPU time.</summary>
    public int StrategyTimeoutMs { get; private set; } = global::URWPGSim2D.Hosting.MatchBuilder.DefaultStrategyTimeoutMs;

    /// <summary>Folder of a Slurm job array for the batch (<c>--slurm DIR</c>), or null to play the batch here.</summary>
    public string? Slurm { get; private set; }

    /// <summary>Shards (array tasks) of a <c>--slurm</c> batch (<c>--shards K</c>), or null for the default.</summary>
    public int? SlurmShards { get; private set; }

    /// <summary>Slurm partition of the jobs (<c>--partition P</c>), or null for the cluster's default.</summary>
    public string? Partition { get; private set; }

    /// <summary>Slurm time limit of each job (<c>--time T</c>, sbatch's format), or null for the partition's default.</summary>
    public string? TimeLimit { get; private set; }

    /// <summary>Further sbatch options of both jobs (<c>--sbatch-arg ARG</c>, repeatable), in order.</summary>
    public IReadOnlyList<string> SbatchArguments => _sbatchArguments;

    private readonly List<string> _sbatchArguments = [];

    /// <summary>A bash file the jobs source before the server starts (<c>--slurm-setup FILE</c>), or null.</summary>
    public string? SlurmSetup { get; private set; }

    /// <summary>Whether to submit the written Slurm jobs (<c>--submit</c>).</summary>
    public bool Submit { get; private set; }

    /// <summary>
    /// The arguments as given but for the options of <c>--slurm</c> itself (<c>--slurm</c>,
    /// <c>--shards</c>, <c>--partition</c>, <c>--time</c>, <c>--sbatch-arg</c>, <c>--slurm-setup</c>,
    /// <c>--results</c>, <c>--submit</c>): what
    /// every task of a Slurm batch passes on, so it plays exactly the batch asked for.
    /// </summary>
    public IReadOnlyList<string> PassedOn { get; private set; } = [];

    /// <summary>Whether --help was given.</summary>
    public bool Help { get; private set; }

    /// <summary>Cycles to play: <c>--cycles</c>, else <c>--minutes</c> × 600, else the scenario's.</summary>
    public int CyclesFor(global::URWPGSim2D.Engine.Scenario.ScenarioDefinition scenario) => Cycles ?? (Minutes * 600) ?? scenario.Cycles;

    /// <summary>Parses the arguments after "run".</summary>
    public static RunOptions Parse(ReadOnlySpan<string> args) => Parse(CliApp.Default.Words("run", args));

    /// <summary>Parses the words after "run", as the parser classified them (<see cref="RunSyntax"/>).</summary>
    public static RunOptions Parse(IReadOnlyList<CommandLineWord> words)
    {
        ArgumentNullException.ThrowIfNull(words);
        var o = new RunOptions();
        var seen = new HashSet<string>(StringComparer.Ordinal);
        var passedOn = new List<string>(2 * words.Count);
        foreach (var word in words)
        {
            string name = word.Name;
            if (word.Option == RunSyntax.Help)
            {
                o.Help = true;
                continue;
            }

            if (!IsSlurmOwn(name))
            {
                passedOn.Add(word.Text);
                if (word.Value is not null)
                {
                    passedOn.Add(word.Value);
                }
            }

            if (word.Option == RunSyntax.ListItems)
            {
                o.ListItems = true;
                continue;
            }

            if (name == "--submit" && word.IsOption)
            {
                o.Submit = seen.Add(name) ? true : throw UsageError("--submit given twice");
                continue;
            }

            if (!name.StartsWith("--", StringComparison.Ordinal))
            {
                throw UsageError($"unexpected argument {MessageText.Quote(name)}");
            }

            if (name is "--live" or "--paused" or "--force" or "--debug-draw" or "--strategy-log")
            {
                if (!seen.Add(name))
                {
                    throw UsageError($"{name} given twice");
                }

                o.Live |= name == "--live";
                o.Paused |= name == "--paused";
                o.Force |= name == "--force";
                o.DebugDraw |= name == "--debug-draw";
                o.StrategyLog |= name == "--strategy-log";
                continue;
            }

            if (!word.IsOption)
            {
                throw CliUsageException.UnknownOption("run", name, RunSyntax.Command, CliApp.ProgramName + " " + Usage);
            }

            string value = word.Value ?? throw UsageError($"{name} needs a value");
            if (name is not ("--strategy" or "--remote-token" or "--sbatch-arg") && !seen.Add(name))
            {
                throw UsageError($"{name} given twice");
            }

            switch (name)
            {
                case "--scenario": o.Scenario = value; break;
                case "--item":
                    o.Item = string.Equals(value, "default", StringComparison.OrdinalIgnoreCase) ? "default"
                        : ItemRegistry.Find(value) is not null ? value
                        : throw ItemList.Unknown("run", value, withDefault: true);
                    break;
                case "--minutes":
                    o.Minutes = value switch { "10" => 10, "5" => 5, "3" => 3, "1" => 1, _ => throw UsageError($"--minutes must be 10, 5, 3 or 1, got {MessageText.Quote(value)}") };
                    break;
                case "--crowd": o.Crowd = (int)Number(name, value, global::URWPGSim2D.Engine.Scenario.CrowdScenario.MinimumMovers, 1_000_000); break;
                case "--batch": o.Batch = (int)Number(name, value, 1, MaximumBatch); break;
                case "--threads": o.Threads = (int)Number(name, value, 1, 1024); break;
                case "--results": o.Results = value; break;
                case "--slurm": o.Slurm = value.Length > 0 ? value : throw UsageError("--slurm needs a folder, got \"\""); break;
                case "--shards": o.SlurmShards = (int)Number(name, value, 1, global::URWPGSim2D.Tournament.Batch.Slurm.SlurmJob.MaximumShards); break;
                case "--partition": o.Partition = global::URWPGSim2D.Tournament.Batch.Slurm.SlurmJob.IsPartition(value) ? value : throw UsageError($"--partition must be a Slurm partition name (letters, digits, '_', '-', '.', comma-separated), got {MessageText.Quote(value)}"); break;
                case "--time": o.TimeLimit = global::URWPGSim2D.Tournament.Batch.Slurm.SlurmJob.IsTimeLimit(value) ? value : throw UsageError($"--time must be a Slurm time limit (M, M:S, H:M:S, D-H, D-H:M, D-H:M:S or infinite), got {MessageText.Quote(value)}"); break;
                case "--sbatch-arg": o._sbatchArguments.Add(global::URWPGSim2D.Tournament.Batch.Slurm.SlurmJob.SbatchArgumentError(value) is { } why ? throw UsageError(why) : value); seen.Add(name); break;
                case "--slurm-setup": o.SlurmSetup = value; break;
                case "--shard": o.ParseShard(value); break;
                case "--trace": o.Trace = value; break;
                case "--svg": o.Svg = value; break;
                case "--html": o.Html = value; break;
                case "--strategies": o.StrategiesFolder = value; break;
                case "--port": o.Port = (int)Number(name, value, 1, 65535); break;
                case "--host": o.Host = LiveOptions.Host(value, UsageError); break;
                case "--speed": o.Speed = LiveOptions.Speed(value, UsageError); break;
                case "--cycles": o.Cycles = (int)Number(name, value, 0, int.MaxValue); break;
                case "--seed": o.Seed = (ulong)Number(name, value, 0, long.MaxValue); break;
                case "--strategy-timeout": o.StrategyTimeoutMs = (int)Number(name, value, 1, 600_000); break;
                case "--time-bank": o.TimeBank = System.TimeSpan.FromSeconds(Number(name, value, 0, 86_400)); break;
                case var host when HostOptions.Is(host): o.HostSettings = HostOptions.Apply(o.HostSettings, name, value, UsageError); break;
                case "--noise":
                    o.Noise = value switch { "on" => true, "off" => false, _ => throw UsageError($"--noise must be on or off, got {MessageText.Quote(value)}") };
                    break;
                case "--strategy":
                    int eq = value.IndexOf('=', StringComparison.Ordinal);
                    if (eq != 1 || value[0] is < '0' or > '3' || eq + 1 >= value.Length)
                    {
                        throw UsageError($"--strategy must be TEAM=SPEC with TEAM 0 to 3, got {MessageText.Quote(value)}");
                    }

                    o.Strategies[value[0] - '0'] = value[(eq + 1)..];
                    o.RemotePorts[value[0] - '0'] = value.AsSpan(eq + 1).StartsWith(RemotePrefix, StringComparison.Ordinal)
                        ? (int)Number("--strategy TEAM=remote:PORT", value[(eq + 1 + RemotePrefix.Length)..], 0, 65535)
                        : null;
                    break;
                case "--remote-wait": o.RemoteWaitSeconds = (int)Number(name, value, 1, 86_400); break;
                case "--remote-host":
                    o.RemoteHost = System.Net.IPAddress.TryParse(value, out var address) && value.Length > 0
                        ? address : throw UsageError($"--remote-host must be an IP address (127.0.0.1, 0.0.0.0, ::1, ...), got {MessageText.Quote(value)}");
                    seen.Add(name);
                    break;
                case "--remote-token": o.ParseToken(value, seen); break;
                default:
                    throw CliUsageException.UnknownOption("run", name, RunSyntax.Command, CliApp.ProgramName + " " + Usage);
            }
        }

        o.PassedOn = passedOn;
        o.Check(seen);
        return o;
    }

    // The options of --slurm itself, which the Slurm tasks do not pass on.
    private static bool IsSlurmOwn(string name) =>
        name == "--results" || SlurmSyntax.Is(name);

    /// <summary>What <c>--strategy TEAM=</c> starts with for a remote team.</summary>
    public const string RemotePrefix = "remote:";

    private readonly bool[] _tokenFor = new bool[4];

    // TOKEN (every remote team) or TEAM=TOKEN; printable, at most the protocol's text length.
    private void ParseToken(string value, HashSet<string> seen)
    {
        bool perTeam = value.Length > 2 && value[0] is >= '0' and <= '3' && value[1] == '=';
        string token = perTeam ? value[2..] : value;
        if (token.Length == 0 || token.Length > URWPGSim2D.Protocol.ProtocolLimits.TextChars || token.Any(char.IsControl))
        {
            throw UsageError($"--remote-token must be [TEAM=]TOKEN, 1..{URWPGSim2D.Protocol.ProtocolLimits.TextChars} characters without control characters, got {MessageText.Quote(value.Length > 40 ? value[..40] + "..." : value)}");
        }

        for (int t = 0; t < RemoteTokens.Length; t++)
        {
            if (!perTeam || value[0] - '0' == t)
            {
                if (RemoteTokens[t] is not null)
                {
                    throw UsageError($"--remote-token given twice for team {t}");
                }

                RemoteTokens[t] = token;
                _tokenFor[t] = perTeam;
            }
        }

        seen.Add("--remote-token");
    }

    // "I/K" with 0 ≤ I < K.
    private void ParseShard(string value)
    {
        int slash = value.IndexOf('/', StringComparison.Ordinal);
        if (slash <= 0
            || !int.TryParse(value.AsSpan(0, slash), NumberStyles.None, CultureInfo.InvariantCulture, out int index)
            || !int.TryParse(value.AsSpan(slash + 1), NumberStyles.None, CultureInfo.InvariantCulture, out int count)
            || count < 1 || index >= count)
        {
            throw UsageError($"--shard must be I/K with 0 <= I < K (e.g. 0/4), got {MessageText.Quote(value)}");
        }

        ShardIndex = index;
        ShardCount = count;
    }

    // Options that do not go together.
    private void Check(HashSet<string> seen)
    {
        if (Help)
        {
            return;
        }

        if ((Scenario is not null ? 1 : 0) + (Crowd is not null ? 1 : 0) + (Item is not null ? 1 : 0) > 1)
        {
            throw UsageError("--item, --scenario and --crowd each choose the scene; give one");
        }

        if (Minutes is not null && Cycles is not null)
        {
            throw UsageError("--minutes and --cycles both set the length; give one");
        }

        if (Batch is null && (ShardCount > 1 || Results is not null))
        {
            throw UsageError("--shard and --results belong to --batch N");
        }

        if (Batch is not null && (Trace is not null || Svg is not null || Html is not null))
        {
            throw UsageError("--trace, --svg and --html record one match; they do not go with --batch");
        }

        if (!Live && (seen.Contains("--port") || seen.Contains("--host") || seen.Contains("--speed") || Paused))
        {
            throw UsageError("--port, --host, --speed and --paused belong to --live");
        }

        if (!Live && StrategiesFolder is not null)
        {
            throw UsageError($"--strategies {MessageText.Quote(StrategiesFolder)} belongs to --live (the control board of the live view)");
        }

        if (Live && (Batch is not null || Trace is not null || Svg is not null || Html is not null))
        {
            throw UsageError("--live plays the match in the browser; --batch, --trace, --svg and --html do not go with it");
        }

        if (DebugDraw && !Live && Trace is null && Html is null)
        {
            throw UsageError("--debug-draw records the strategies' drawings in --trace, --html or --live; give one of them");
        }

        if (StrategyLog && (Batch is not null || Slurm is not null))
        {
            throw UsageError("--strategy-log shows what the strategies print in one match (the terminal, --trace, --html or --live); it does not go with --batch or --slurm");
        }

        CheckSlurm();
        CheckRemote(seen);
    }

    // The options of remote teams (docs/cli.md, "Remote teams").
    private void CheckRemote(HashSet<string> seen)
    {
        bool remote = RemotePorts.Any(p => p is not null);
        if (!remote && (seen.Contains("--remote-wait") || seen.Contains("--remote-host") || seen.Contains("--remote-token")))
        {
            throw UsageError("--remote-wait, --remote-host and --remote-token belong to --strategy TEAM=remote:PORT");
        }

        if (remote && (Batch is not null || Slurm is not null))
        {
            throw UsageError("a remote team plays one match at a time: --batch and --slurm do not go with --strategy TEAM=remote:PORT");
        }

        if (remote && StrategiesFolder is not null)
        {
            throw UsageError("the control board (--strategies) chooses strategies from its folder: it does not go with --strategy TEAM=remote:PORT");
        }

        for (int a = 0; a < RemotePorts.Length; a++)
        {
            for (int b = a + 1; b < RemotePorts.Length; b++)
            {
                if (RemotePorts[a] is int port && port != 0 && RemotePorts[b] == port)
                {
                    throw UsageError($"both remote teams ask for port {port}; give each its own (or 0 for any free one)");
                }
            }
        }

        for (int t = 0; t < _tokenFor.Length; t++)
        {
            if (_tokenFor[t] && RemotePorts[t] is null)
            {
                throw UsageError($"--remote-token for team {t}, which is not remote");
            }
        }
    }

    // The options of a Slurm batch (docs/batch.md, "On a Slurm cluster").
    private void CheckSlurm()
    {
        if (Slurm is null && (SlurmShards is not null || Partition is not null || TimeLimit is not null || Submit || SbatchArguments.Count > 0 || SlurmSetup is not null))
        {
            throw UsageError("--shards, --partition, --time, --sbatch-arg, --slurm-setup and --submit belong to --slurm DIR");
        }

        if (Slurm is null)
        {
            return;
        }

        if (Batch is null)
        {
            throw UsageError("--slurm DIR belongs to --batch N");
        }

        if (ShardCount > 1)
        {
            throw UsageError("--slurm makes the shards itself (--shards K); --shard I/K does not go with it");
        }

        if (SlurmShards > Batch)
        {
            throw UsageError($"--shards {SlurmShards} is more than the {Batch} matches of --batch");
        }

        if (Scenario == "-")
        {
            throw UsageError("--scenario - (standard input) cannot be read again by the Slurm tasks; give a file");
        }
    }

    private static long Number(string name, string value, long min, long max)
    {
        if (!long.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out long v) || v < min || v > max)
        {
            throw UsageError($"{name} must be an integer {min}..{max}, got {MessageText.Quote(value)}");
        }

        return v;
    }

    private static CliUsageException UsageError(string message) => new("run: " + message, CliApp.ProgramName + " " + Usage);
}
