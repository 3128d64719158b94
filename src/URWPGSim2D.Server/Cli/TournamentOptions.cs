using URWPGSim2D.Tournament.Batch.Slurm;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Server.Cli;

/// <summary>The parsed arguments of <c>tournament</c>; every check that needs no file but the entrants' is made here.</summary>
internal sealed class TournamentOptions
{
    /// <summary>The command's synopsis in the program's help.</summary>
    public const string Synopsis = "tournament --item ITEM --entrant NAME=SPEC... --out DIR [options]";

    /// <summary>The command's full usage (<see cref="TournamentSyntax.Usage"/>).</summary>
    public static string Usage { get; } = "tournament " + TournamentSyntax.Usage.Text;

    /// <summary>Most entrants.</summary>
    public const int MaximumEntrants = 1000;

    /// <summary>Longest entrant name.</summary>
    public const int MaximumName = 64;

    /// <summary>The item.</summary>
    public CompetitionItem Item { get; private set; } = null!;

    /// <summary>The entrants, in command-line order.</summary>
    public List<Entrant> Entrants { get; } = [];

    /// <summary>Seeds per pairing (default 4).</summary>
    public int Seeds { get; private set; } = 4;

    /// <summary>The first seed (default 1).</summary>
    public ulong FirstSeed { get; private set; } = 1;

    /// <summary>Cycles per match (<c>--minutes</c> × 600 or <c>--cycles</c>; default 10 minutes).</summary>
    public int Cycles { get; private set; } = 6000;

    /// <summary>Strategies' time limit per call, ms.</summary>
    public int StrategyTimeoutMs { get; private set; } = global::URWPGSim2D.Hosting.MatchBuilder.DefaultStrategyTimeoutMs;

    /// <summary>Where user entrants run (<see cref="HostOptions"/>): strategy hosts by default, as <c>run</c>.</summary>
    public HostSettings HostSettings { get; private set; } = HostSettings.Default;

    /// <summary>Whether strategy hosts run in the sandbox.</summary>
    public SandboxMode Sandbox => HostSettings.Sandbox;

    /// <summary>Matches at once, or null for every core.</summary>
    public int? Threads { get; private set; }

    /// <summary>Whether to write every match's replay page.</summary>
    public bool Replays { get; private set; }

    /// <summary>The output folder.</summary>
    public string Out { get; private set; } = null!;

    /// <summary>Every option of <c>tournament</c>: those <see cref="Usage"/> names.</summary>
    public static IReadOnlyList<string> KnownOptions { get; } = CliSyntax.LongNames(TournamentSyntax.Command);

    /// <summary>Whether the matches are played one after another in the live page (<c>--live</c>).</summary>
    public bool Live { get; private set; }

    /// <summary>How long a match waits for a remote entrant's client (<c>--remote-wait SECONDS</c>; default 60).</summary>
    public int RemoteWaitSeconds { get; private set; } = RemoteSeat.DefaultWaitSeconds;

    /// <summary>The address remote entrants listen on (<c>--remote-host ADDR</c>; loopback by default).</summary>
    public System.Net.IPAddress RemoteHost { get; private set; } = System.Net.IPAddress.Loopback;

    /// <summary>Whether some entrant plays remotely (<c>--entrant NAME=remote:PORT</c>).</summary>
    public bool AnyRemote => Entrants.Exists(e => e.RemotePort is not null);

    private readonly List<string> _tokens = [];
    private readonly Dictionary<string, string> _tokenOf = new(StringComparer.Ordinal);
    private string? _tokenForAll;

    /// <summary>The token remote entrant <paramref name="name"/>'s client must present (<c>--remote-token [NAME=]TOKEN</c>), or null.</summary>
    public string? RemoteToken(string name) => _tokenOf.TryGetValue(name, out string? token) ? token : _tokenForAll;

    /// <summary>Port of the live page (<c>--port N</c>).</summary>
    public int Port { get; private set; } = RunOptions.DefaultPort;

    /// <summary>Address the live page listens on (<c>--host H</c>).</summary>
    public string Host { get; private set; } = "127.0.0.1";

    /// <summary>Live speed, times real time (<c>--speed X</c>).</summary>
    public double Speed { get; private set; } = 1;

    /// <summary>The Slurm jobs' folder, or null.</summary>
    public string? Slurm { get; private set; }

    /// <summary>Shards of the Slurm job array, or null for the default.</summary>
    public int? SlurmShards { get; private set; }

    /// <summary>Slurm partition, or null.</summary>
    public string? Partition { get; private set; }

    /// <summary>Slurm time limit, or null.</summary>
    public string? TimeLimit { get; private set; }

    /// <summary>Further sbatch options of both jobs (<c>--sbatch-arg ARG</c>, repeatable), in order.</summary>
    public List<string> SbatchArguments { get; } = [];

    /// <summary>A bash file the jobs source before the server starts (<c>--slurm-setup FILE</c>), or null.</summary>
    public string? SlurmSetup { get; private set; }

    /// <summary>Whether to submit the Slurm jobs.</summary>
    public bool Submit { get; private set; }

    /// <summary>This process's shard index (with <c>--shard I/K</c>).</summary>
    public int ShardIndex { get; private set; }

    /// <summary>Shards (1: the whole tournament).</summary>
    public int ShardCount { get; private set; } = 1;

    /// <summary>The shard's result file (with <c>--shard</c>).</summary>
    public string? Results { get; private set; }

    /// <summary>Shard result files to gather (<c>--merge FILE...</c>).</summary>
    public List<string> Merge { get; } = [];

    /// <summary>The arguments but the Slurm options' own and <c>--merge</c>'s: what the Slurm tasks pass on.</summary>
    public IReadOnlyList<string> PassedOn { get; private set; } = [];

    /// <summary>Whether --help was given.</summary>
    public bool Help { get; private set; }

    /// <summary>The format: <c>round-robin</c> (the default) or <c>groups-knockout</c> (<c>--format</c>).</summary>
    public string Format { get; private set; } = RoundRobin;

    /// <summary>The round robin's format name.</summary>
    public const string RoundRobin = "round-robin";

    /// <summary>The group stage and knockout's format name.</summary>
    public const string GroupsKnockoutFormat = "groups-knockout";

    /// <summary>Groups of the group stage (<c>--groups G</c>, default 2).</summary>
    public int Groups { get; private set; } = 2;

    /// <summary>Entrants of each group into the knockout (<c>--advance K</c>, default 2).</summary>
    public int Advance { get; private set; } = 2;

    /// <summary>Seeds of the final (<c>--final-seeds F</c>), or null for <see cref="Seeds"/>.</summary>
    public int? FinalSeeds { get; private set; }

    /// <summary>The entrants named first in the seeding (<c>--seeding NAME,…</c>), the others after them in entrant order.</summary>
    public List<string> Seeding { get; } = [];

    /// <summary>With <c>--format groups-knockout</c>: the groups and the group stage; null for a round robin.</summary>
    public GroupsKnockout? Cup { get; private set; }

    /// <summary>Whether only to check the entrants (<c>--check</c>): each loads and plays one short match against idle; nothing is written.</summary>
    public bool Check { get; private set; }

    /// <summary>Parses the arguments after <c>tournament</c>.</summary>
    public static TournamentOptions Parse(ReadOnlySpan<string> args) => Parse(CliApp.Default.Words("tournament", args));

    /// <summary>Parses the words after <c>tournament</c>, as the parser classified them (<see cref="TournamentSyntax"/>).</summary>
    public static TournamentOptions Parse(IReadOnlyList<CommandLineWord> words)
    {
        ArgumentNullException.ThrowIfNull(words);
        var o = new TournamentOptions();
        var seen = new HashSet<string>(StringComparer.Ordinal);
        var passedOn = new List<string>();
        for (int i = 0; i < words.Count; i++)
        {
            var word = words[i];
            string name = word.Name;
            if (word.Option == TournamentSyntax.Help)
            {
                o.Help = true;
                return o;
            }

            if (word.Option == TournamentSyntax.Merge)
            {
                if (!seen.Add(name))
                {
                    throw UsageError("--merge given twice");
                }

                // Every word after --merge is a result file, as written.
                var files = new List<string>();
                if (word.Value is not null)
                {
                    files.Add(word.Value);
                }

                foreach (var rest in words.Skip(i + 1))
                {
                    files.Add(rest.Text);
                    if (rest.Value is not null)
                    {
                        files.Add(rest.Value);
                    }
                }

                foreach (string file in files)
                {
                    o.Merge.Add(file.Length > 0 ? file : throw UsageError("--merge needs result files, got \"\""));
                }

                if (o.Merge.Count == 0)
                {
                    throw UsageError("--merge needs at least one result file");
                }

                break;
            }

            if (name == "--check")
            {
                if (!seen.Add(name))
                {
                    throw UsageError("--check given twice");
                }

                o.Check = true;
                continue;
            }

            if (name is "--replays" or "--submit" or "--live")
            {
                if (!seen.Add(name))
                {
                    throw UsageError($"{name} given twice");
                }

                o.Replays |= name == "--replays";
                o.Submit |= name == "--submit";
                o.Live |= name == "--live";
                if (name == "--replays")
                {
                    passedOn.Add(name);
                }

                continue;
            }

            if (!name.StartsWith("--", StringComparison.Ordinal))
            {
                throw UsageError($"unexpected argument {MessageText.Quote(name)}");
            }

            if (!word.IsOption)
            {
                throw CliUsageException.UnknownOption("tournament", name, TournamentSyntax.Command, CliApp.ProgramName + " " + Usage);
            }

            string value = word.Value ?? throw UsageError($"{name} needs a value");
            if (name is not ("--entrant" or "--sbatch-arg" or "--remote-token") && !seen.Add(name))
            {
                throw UsageError($"{name} given twice");
            }

            if (!SlurmSyntax.Is(name) && name is not ("--shard" or "--results"))
            {
                passedOn.Add(name);
                passedOn.Add(value);
            }

            switch (name)
            {
                case "--item":
                    o.Item = ItemRegistry.Find(value) ?? throw ItemList.Unknown("tournament", value, withDefault: false);
                    break;
                case "--entrant": o.Entrants.Add(ParseEntrant(value)); break;
                case "--entrants-dir": o.Entrants.InsertRange(0, EntrantsOf(value)); break;
                case "--seeds": o.Seeds = (int)Number(name, value, 1, 100_000); break;
                case "--seed": o.FirstSeed = (ulong)Number(name, value, 0, long.MaxValue); break;
                case "--minutes":
                    o.Cycles = value switch { "10" => 6000, "5" => 3000, "3" => 1800, "1" => 600, _ => throw UsageError($"--minutes must be 10, 5, 3 or 1, got {MessageText.Quote(value)}") };
                    break;
                case "--cycles": o.Cycles = (int)Number(name, value, 1, 1_000_000); break;
                case "--strategy-timeout": o.StrategyTimeoutMs = (int)Number(name, value, 1, 600_000); break;
                case var host when HostOptions.Is(host): o.HostSettings = HostOptions.Apply(o.HostSettings, name, value, UsageError); break;
                case "--threads": o.Threads = (int)Number(name, value, 1, 1024); break;
                case "--out": o.Out = value.Length > 0 ? value : throw UsageError("--out needs a folder, got \"\""); break;
                case "--slurm": o.Slurm = value.Length > 0 ? value : throw UsageError("--slurm needs a folder, got \"\""); break;
                case "--shards": o.SlurmShards = (int)Number(name, value, 1, SlurmJob.MaximumShards); break;
                case "--partition": o.Partition = SlurmJob.IsPartition(value) ? value : throw UsageError($"--partition must be a Slurm partition name (letters, digits, '_', '-', '.', comma-separated), got {MessageText.Quote(value)}"); break;
                case "--time": o.TimeLimit = SlurmJob.IsTimeLimit(value) ? value : throw UsageError($"--time must be a Slurm time limit (M, M:S, H:M:S, D-H, D-H:M, D-H:M:S or infinite), got {MessageText.Quote(value)}"); break;
                case "--sbatch-arg": o.SbatchArguments.Add(SlurmJob.SbatchArgumentError(value) is { } why ? throw UsageError(why) : value); seen.Add(name); break;
                case "--slurm-setup": o.SlurmSetup = value; break;
                case "--shard": o.ParseShard(value); break;
                case "--format": o.Format = value is RoundRobin or GroupsKnockoutFormat ? value : throw UsageError($"--format must be {RoundRobin} or {GroupsKnockoutFormat}, got {MessageText.Quote(value)}"); break;
                case "--groups": o.Groups = (int)Number(name, value, 1, MaximumEntrants / 2); break;
                case "--advance": o.Advance = (int)Number(name, value, 1, MaximumEntrants); break;
                case "--final-seeds": o.FinalSeeds = (int)Number(name, value, 1, 100_000); break;
                case "--seeding":
                    foreach (string entrant in value.Split(','))
                    {
                        o.Seeding.Add(entrant.Length > 0 ? entrant : throw UsageError($"--seeding must be entrant names separated by commas, got {MessageText.Quote(value)}"));
                    }

                    break;
                case "--port": o.Port = (int)Number(name, value, 1, 65535); break;
                case "--host": o.Host = LiveOptions.Host(value, UsageError); break;
                case "--speed": o.Speed = LiveOptions.Speed(value, UsageError); break;
                case "--results": o.Results = value.Length > 0 ? value : throw UsageError("--results needs a file, got \"\""); break;
                case "--remote-wait": o.RemoteWaitSeconds = (int)Number(name, value, 1, 86_400); break;
                case "--remote-host":
                    o.RemoteHost = System.Net.IPAddress.TryParse(value, out var address) && value.Length > 0
                        ? address : throw UsageError($"--remote-host must be an IP address (127.0.0.1, 0.0.0.0, ::1, ...), got {MessageText.Quote(value)}");
                    break;
                case "--remote-token": o._tokens.Add(value); seen.Add(name); break;
                default: throw CliUsageException.UnknownOption("tournament", name, TournamentSyntax.Command, CliApp.ProgramName + " " + Usage);
            }
        }

        o.PassedOn = passedOn;
        o.CheckAll(seen);
        return o;
    }

    private void CheckAll(HashSet<string> seen)
    {
        if (Item is null)
        {
            throw UsageError("--item ITEM is required (the item the entrants play)");
        }

        if (Out is null && !Check)
        {
            throw UsageError("--out DIR is required (the folder of the results, standings and report)");
        }

        if (seen.Contains("--minutes") && seen.Contains("--cycles"))
        {
            throw UsageError("--minutes and --cycles both set the length; give one");
        }

        int least = Item.TeamCount >= 2 ? 2 : 1;
        if (Entrants.Count < least)
        {
            throw UsageError($"--entrant: {Item.Slug} is a {Item.TeamCount}-team item and needs at least {least} entrants, got {Entrants.Count}");
        }

        if (Entrants.Count > MaximumEntrants)
        {
            throw UsageError($"--entrant: at most {MaximumEntrants} entrants, got {Entrants.Count}");
        }

        var names = new HashSet<string>(StringComparer.Ordinal);
        foreach (var e in Entrants)
        {
            if (!names.Add(e.Name))
            {
                throw UsageError($"--entrant: the name {MessageText.Quote(e.Name)} is given twice (names must differ)");
            }
        }

        // Each entrant's version: a hash of its files, so that a changed entrant's matches are played again.
        for (int i = 0; i < Entrants.Count; i++)
        {
            var e = Entrants[i];
            if (e.Spec == Entrant.Demo || StrategyResolver.BuiltInNames.Contains(e.Spec) || e.RemotePort is not null)
            {
                continue;
            }

            try
            {
                Entrants[i] = e with { Version = EntrantFiles.Version(e.Spec) };
            }
            catch (Exception x) when (x is IOException or UnauthorizedAccessException)
            {
                throw UsageError($"--entrant {e.Name}: cannot read {MessageText.Quote(e.Spec)} ({x.Message})");
            }
        }

        CheckFormat(seen);
        CheckRemote(seen);
        if ((ShardCount > 1 || seen.Contains("--shard")) != (Results is not null))
        {
            throw UsageError("--shard I/K and --results FILE go together (a Slurm task's share of the tournament)");
        }

        if (Slurm is null && (SlurmShards is not null || Partition is not null || TimeLimit is not null || Submit || SbatchArguments.Count > 0 || SlurmSetup is not null))
        {
            throw UsageError("--shards, --partition, --time, --sbatch-arg, --slurm-setup and --submit belong to --slurm SDIR");
        }

        if (Slurm is not null && (Results is not null || Merge.Count > 0))
        {
            throw UsageError("--slurm writes the jobs; --shard, --results and --merge are what its jobs run, not options of it");
        }

        if (Results is not null && Merge.Count > 0)
        {
            throw UsageError("--merge gathers shards into --out DIR; it does not go with --shard");
        }

        if (!Live && (seen.Contains("--port") || seen.Contains("--host") || seen.Contains("--speed")))
        {
            throw UsageError("--port, --host and --speed belong to --live");
        }

        if (Live && (Check || Slurm is not null || Results is not null || Merge.Count > 0 || Replays))
        {
            throw UsageError("--live plays the matches on this machine, one after another, in the page: it does not go with --check, --slurm, --shard, --merge or --replays");
        }
    }

    // Remote entrants (docs/tournament.md, "Remote entrants") and their options.
    private void CheckRemote(HashSet<string> seen)
    {
        if (!AnyRemote)
        {
            if (seen.Contains("--remote-wait") || seen.Contains("--remote-host") || seen.Contains("--remote-token"))
            {
                throw UsageError("--remote-wait, --remote-host and --remote-token belong to --entrant NAME=remote:PORT");
            }

            return;
        }

        if (Check || Slurm is not null || Results is not null || Merge.Count > 0 || seen.Contains("--shard"))
        {
            throw UsageError("a remote entrant plays its matches here, one at a time, with its client: --check, --slurm, --shard and --merge do not go with --entrant NAME=remote:PORT");
        }

        var ports = new Dictionary<int, string>();
        foreach (var e in Entrants)
        {
            if (e.RemotePort is int port && port != 0 && !ports.TryAdd(port, e.Name))
            {
                throw UsageError($"remote entrants {ports[port]} and {e.Name} both ask for port {port}; give each its own (or 0 for any free one)");
            }
        }

        foreach (string value in _tokens)
        {
            int eq = value.IndexOf('=', StringComparison.Ordinal);
            string? owner = eq > 0 && Entrants.Exists(e => e.Name == value[..eq]) ? value[..eq] : null;
            string token = owner is null ? value : value[(eq + 1)..];
            if (token.Length == 0 || token.Length > URWPGSim2D.Protocol.ProtocolLimits.TextChars || token.Any(char.IsControl))
            {
                throw UsageError($"--remote-token must be [NAME=]TOKEN, 1..{URWPGSim2D.Protocol.ProtocolLimits.TextChars} characters without control characters, got {MessageText.Quote(value.Length > 40 ? value[..40] + "..." : value)}");
            }

            if (owner is not null && Entrants.Find(e => e.Name == owner)!.RemotePort is null)
            {
                throw UsageError($"--remote-token for entrant {owner}, which is not remote");
            }

            if (owner is null ? _tokenForAll is not null : !_tokenOf.TryAdd(owner, token))
            {
                throw UsageError($"--remote-token given twice for {(owner is null ? "every remote entrant" : "entrant " + owner)}");
            }

            _tokenForAll ??= owner is null ? token : null;
        }
    }

    // --format groups-knockout and its options: a two-team item, one machine, and counts the entrants can fill.
    private void CheckFormat(HashSet<string> seen)
    {
        if (Format == RoundRobin)
        {
            if (seen.Contains("--groups") || seen.Contains("--advance") || seen.Contains("--final-seeds") || seen.Contains("--seeding"))
            {
                throw UsageError("--groups, --advance, --final-seeds and --seeding belong to --format groups-knockout");
            }

            return;
        }

        if (Item.TeamCount != 2)
        {
            throw UsageError($"--format groups-knockout: {Item.Slug} is a {Item.TeamCount}-team item; a group stage and knockout needs a two-team item");
        }

        if (Slurm is not null || Results is not null || Merge.Count > 0)
        {
            throw UsageError("--format groups-knockout is played on one machine (each knockout round is paired from the results before it, so its matches cannot be laid out as Slurm tasks in advance): --slurm, --shard, --results and --merge go with --format round-robin");
        }

        var index = new Dictionary<string, int>(StringComparer.Ordinal);
        for (int i = 0; i < Entrants.Count; i++)
        {
            index[Entrants[i].Name] = i;
        }

        var order = new List<int>();
        foreach (string name in Seeding)
        {
            if (!index.TryGetValue(name, out int e))
            {
                throw UsageError($"--seeding: {MessageText.Quote(name)} is not an entrant");
            }

            if (order.Contains(e))
            {
                throw UsageError($"--seeding: {MessageText.Quote(name)} is named twice");
            }

            order.Add(e);
        }

        order.AddRange(Enumerable.Range(0, Entrants.Count).Where(e => !order.Contains(e)));
        try
        {
            Cup = new GroupsKnockout(Entrants.Count, Groups, Advance, Seeds, FinalSeeds ?? Seeds, FirstSeed, order);
        }
        catch (ArgumentException e)
        {
            throw UsageError(e.Message);
        }
    }

    // --entrants-dir DIR: every sub-folder, .cs file and DLL in DIR, named after it.
    private static List<Entrant> EntrantsOf(string folder)
    {
        if (!Directory.Exists(folder))
        {
            throw UsageError($"--entrants-dir must be a folder, got {MessageText.Quote(folder)}");
        }

        List<Entrant> entrants;
        try
        {
            entrants = EntrantFiles.Of(folder);
        }
        catch (ArgumentException e)
        {
            throw UsageError($"--entrants-dir {MessageText.Quote(folder)}: {e.Message}");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw UsageError($"--entrants-dir {MessageText.Quote(folder)}: cannot read it ({e.Message})");
        }

        if (entrants.Count == 0)
        {
            throw UsageError($"--entrants-dir {MessageText.Quote(folder)} holds no sub-folder, .cs file or .dll file");
        }

        foreach (var e in entrants)
        {
            if (e.Name.Length > MaximumName || e.Name.AsSpan().IndexOfAnyInRange('\0', '\u001f') >= 0 || e.Name.Contains('\u007f', StringComparison.Ordinal) || e.Name.Trim() != e.Name)
            {
                throw UsageError($"--entrants-dir: an entrant's name must be 1-{MaximumName} printable characters without spaces at its ends, got {MessageText.Quote(e.Name)} ({MessageText.Quote(e.Spec)})");
            }
        }

        return entrants;
    }

    // NAME=SPEC: a name of printable characters without '=', and a SPEC that names something.
    private static Entrant ParseEntrant(string value)
    {
        int eq = value.IndexOf('=', StringComparison.Ordinal);
        if (eq <= 0 || eq == value.Length - 1)
        {
            throw UsageError($"--entrant must be NAME=SPEC (e.g. mine=strategies/Mine.cs, or rival=demo), got {MessageText.Quote(value)}");
        }

        string name = value[..eq], spec = value[(eq + 1)..];
        if (name.Length > MaximumName || name.AsSpan().IndexOfAnyInRange('\0', '\u001f') >= 0 || name.Contains('\u007f', StringComparison.Ordinal) || name.Trim() != name)
        {
            throw UsageError($"--entrant: a name must be 1-{MaximumName} printable characters without spaces at its ends, got {MessageText.Quote(name)}");
        }

        if (spec == Entrant.Demo || StrategyResolver.BuiltInNames.Contains(spec))
        {
            return new Entrant(name, spec);
        }

        if (spec.StartsWith(Entrant.RemotePrefix, StringComparison.Ordinal))
        {
            return new Entrant(name, Entrant.RemotePrefix + Number("--entrant NAME=remote:PORT", spec[Entrant.RemotePrefix.Length..], 0, 65535).ToString(CultureInfo.InvariantCulture));
        }

        int hash = spec.LastIndexOf('#');
        string path = hash > 0 ? spec[..hash] : spec;
        bool exists = File.Exists(path) || Directory.Exists(path) || File.Exists(spec) || Directory.Exists(spec);
        if (!exists)
        {
            throw UsageError($"--entrant {name}: {MessageText.Quote(spec)} is not demo, a built-in strategy ({string.Join(", ", StrategyResolver.BuiltInNames)}), remote:PORT, or an existing .dll, .cs file or folder");
        }

        return new Entrant(name, spec);
    }

    private void ParseShard(string value)
    {
        int slash = value.IndexOf('/', StringComparison.Ordinal);
        if (slash <= 0
            || !int.TryParse(value.AsSpan(0, slash), NumberStyles.None, CultureInfo.InvariantCulture, out int index)
            || !int.TryParse(value.AsSpan(slash + 1), NumberStyles.None, CultureInfo.InvariantCulture, out int count)
            || count < 1 || index >= count || count > SlurmJob.MaximumShards)
        {
            throw UsageError($"--shard must be I/K with 0 <= I < K <= {SlurmJob.MaximumShards} (e.g. 0/4), got {MessageText.Quote(value)}");
        }

        ShardIndex = index;
        ShardCount = count;
    }

    private static long Number(string name, string value, long min, long max) =>
        long.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out long n) && n >= min && n <= max
            ? n
            : throw UsageError($"{name} must be an integer {min}..{max}, got {MessageText.Quote(value)}");

    private static CliUsageException UsageError(string message) => new("tournament: " + message, CliApp.ProgramName + " " + Usage);
}
