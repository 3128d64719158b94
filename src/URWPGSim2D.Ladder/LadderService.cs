using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Threading;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Messages;
using URWPGSim2D.Ladder.Play;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder;

/// <summary>
/// The service's ladders, teams and organiser: each ladder (one item, its match length and first
/// seed) has its core (<see cref="LadderCore"/>); teams, their tokens and passwords, the organiser's
/// token and the settings are the service's. A team that submits plays in every ladder it has a
/// working submission of; a house entrant plays in one ladder. Workers take the ladders in turn.
/// </summary>
internal sealed class LadderService : IDisposable
{
    /// <summary>The built-in strategies a house entrant may play.</summary>
    public static IReadOnlyList<string> HouseStrategies => LadderSettings.HouseStrategies;

    private readonly LadderSettings _settings;
    private readonly object _gate = new();
    private readonly Dictionary<long, LadderCore> _cores = [];
    private int _turn;

    /// <summary>
    /// Migrates the store, creates or reopens the ladder <see cref="LadderSettings.Item"/> names (the
    /// newest when none is named; a ball-grab ladder when there is none), sets the organiser's token
    /// and readies a core for every ladder.
    /// </summary>
    public LadderService(ILadderStore store, LadderSettings settings)
    {
        Store = store;
        _settings = settings;
        Store.Migrate();
        var existing = settings.Item is null ? Store.NewestLadder() : null;
        var item = TwoTeamItem(settings.Item ?? existing?.Item ?? "ball-grab", "--item");
        var ladder = existing ?? Store.OpenLadder(item.Slug, settings.Cycles ?? CompetitionItem.DefaultCycles, 1);
        if (settings.Cycles is { } cycles && cycles != ladder.Cycles)
        {
            Store.SetCycles(ladder.Id, cycles);
        }

        Served = ladder.Id;
        if (settings.AdminToken is { } given)
        {
            Store.SetSetting("admin_token_hash", Secrets.HashToken(given));
        }
        else if (Store.Setting("admin_token_hash") is null)
        {
            NewAdminToken = Secrets.NewToken();
            Store.SetSetting("admin_token_hash", Secrets.HashToken(NewAdminToken));
        }

        foreach (var l in Store.Ladders())
        {
            Core(l.Id);
        }
    }

    /// <summary>Where rows are kept.</summary>
    public ILadderStore Store { get; }

    /// <summary>The ladder named on start (<c>--item</c>), or the newest.</summary>
    public long Served { get; }

    /// <summary>The organiser's token made on this first start (print it once), or null.</summary>
    public string? NewAdminToken { get; }

    /// <summary>Upload limits.</summary>
    public LadderLimits Limits => _settings.Limits;

    /// <summary>Matches this process plays at once.</summary>
    public int Workers => _settings.Workers;

    /// <summary>Told whenever something may give a worker a match to play (a ladder, a team, a submission, a resume, a requeue).</summary>
    public event Action? Changed;

    /// <summary>Every ladder's core, by ladder id.</summary>
    public IReadOnlyList<LadderCore> Cores()
    {
        foreach (var l in Store.Ladders())
        {
            Core(l.Id); // a ladder another process made
        }

        lock (_gate)
        {
            return [.. _cores.Values.OrderBy(c => c.LadderId)];
        }
    }

    /// <summary>The core of ladder <paramref name="id"/>, made the first time it is asked for.</summary>
    /// <exception cref="LadderInputException">There is no such ladder.</exception>
    public LadderCore Core(long id)
    {
        lock (_gate)
        {
            if (_cores.TryGetValue(id, out var core))
            {
                return core;
            }

            var row = Store.Ladder(id) ?? throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"ladder: no ladder {id}"));
            core = LadderCore.Player(Store, _settings, row);
            core.Changed += Touch;
            _cores[id] = core;
            return core;
        }
    }

    /// <summary>
    /// The ladder <paramref name="text"/> names (its id, or its item when one ladder plays it); with
    /// <paramref name="text"/> null or empty, the only ladder.
    /// </summary>
    /// <exception cref="LadderInputException">No ladder is named while there are several, or none is the one named (the message lists them).</exception>
    public LadderCore Choose(string? text)
    {
        var ladders = Store.Ladders();
        if (string.IsNullOrEmpty(text))
        {
            return ladders.Count == 1 ? Core(ladders[0].Id)
                : throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"ladder: this service runs {ladders.Count} ladders; name one: {Choices(ladders)}"));
        }

        if (long.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out long id) && ladders.Any(l => l.Id == id))
        {
            return Core(id);
        }

        var ofItem = ladders.Where(l => l.Item == text).ToList();
        return ofItem.Count switch
        {
            1 => Core(ofItem[0].Id),
            0 => throw new LadderInputException($"ladder: no ladder {MessageText.Quote(text)}; this service runs {Choices(ladders)}"),
            _ => throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"ladder: {ofItem.Count} ladders play {text}; name one by its id: {Choices(ofItem)}")),
        };
    }

    // "1 (ball-grab), 2 (polo-1v1)".
    private static string Choices(IEnumerable<LadderRow> ladders) =>
        string.Join(", ", ladders.Select(l => string.Create(CultureInfo.InvariantCulture, $"{l.Id} ({l.Item})")));

    /// <summary>Creates a ladder of <paramref name="item"/>: matches of <paramref name="cycles"/> cycles, the seed of match N is <paramref name="firstSeed"/> + N.</summary>
    /// <exception cref="LadderInputException">The item is not one of two teams, or the length is out of range.</exception>
    public LadderCore CreateLadder(string item, int cycles, ulong firstSeed)
    {
        var found = TwoTeamItem(item, "item");
        if (cycles < 1 || cycles > MaxCycles)
        {
            throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"cycles must be 1 to {MaxCycles}, got {cycles}"));
        }

        var core = Core(Store.CreateLadder(found.Slug, cycles, firstSeed).Id);
        Touch();
        return core;
    }

    /// <summary>The longest match a ladder plays, in cycles (an hour).</summary>
    public const int MaxCycles = 36_000;

    /// <summary>The items a ladder may play: those of two teams.</summary>
    public static IEnumerable<CompetitionItem> Items => ItemRegistry.All.Where(i => i.TeamCount == 2);

    // The item of a ladder: known, of two teams.
    private static CompetitionItem TwoTeamItem(string slug, string field)
    {
        var item = ItemRegistry.Find(slug) ?? throw new LadderInputException($"{field}: unknown item {MessageText.Quote(slug)}");
        return item.TeamCount == 2 ? item : throw new LadderInputException($"{field}: {item.Slug} is an item of {item.TeamCount} team(s); a ladder plays items of two teams");
    }

    /// <summary>Whether <paramref name="token"/> is the organiser's.</summary>
    public bool IsAdmin(string? token) =>
        token is { Length: > 0 } && Store.Setting("admin_token_hash") is { } stored && Secrets.SameHash(Secrets.HashToken(token), stored);

    /// <summary>The team whose token is <paramref name="token"/>, or null.</summary>
    public TeamRow? TeamOf(string? token) =>
        token is { Length: > 0 } ? Store.TeamByToken(Secrets.HashToken(token)) ?? Store.TeamBySession(Secrets.HashToken(token)) : null;

    /// <summary>A new sign-in token of <paramref name="team"/> (after its password was checked), kept hashed.</summary>
    public string NewSession(TeamRow team)
    {
        string token = Secrets.NewToken();
        Store.AddSession(team.Id, Secrets.HashToken(token));
        return token;
    }

    /// <summary>The most submissions of one team to one ladder per UTC day.</summary>
    public int SubmissionsPerDay => LadderCore.SubmissionsPerDay(Store, Limits);

    /// <summary>Sets the per-day submission limit.</summary>
    public void SetSubmissionsPerDay(int limit)
    {
        if (limit < 1 || limit > 10_000)
        {
            throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"submissionsPerDay must be 1 to 10000, got {limit}"));
        }

        Store.SetSetting("submissions_per_day", limit.ToString(CultureInfo.InvariantCulture));
    }

    /// <summary>
    /// Adds a team and returns it with its token, shown once: a team that submits its own strategies
    /// (to any ladder), or, when <paramref name="house"/> names a built-in strategy, a house entrant of
    /// the ladder <paramref name="ladder"/> names (<see cref="Choose"/>).
    /// </summary>
    public (TeamRow Team, string Token) AddTeam(string name, string? house, string? ladder)
    {
        CheckName(name);
        if (house is not null && !HouseStrategies.Contains(house))
        {
            throw new LadderInputException($"strategy must be {string.Join(", ", HouseStrategies)}, got {MessageText.Quote(house)}");
        }

        if (house is null && !string.IsNullOrEmpty(ladder))
        {
            throw new LadderInputException("ladder: only a house entrant is added to one ladder; a team that submits plays in every ladder it submits to");
        }

        long ladderId = house is null ? 0 : Choose(ladder).LadderId;
        string token = Secrets.NewToken();
        var team = Store.AddTeam(name, Secrets.HashToken(token), house, ladderId) ?? throw new LadderInputException($"name: a team named {MessageText.Quote(name)} exists already");
        Touch();
        return (team, token);
    }

    /// <summary>Sets a team's password (for signing in on the page).</summary>
    public void SetPassword(TeamRow team, string password)
    {
        if (password.Length < 8 || password.Length > 200)
        {
            throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"password must be 8 to 200 characters, got {password.Length}"));
        }

        Store.SetPassword(team.Id, Secrets.HashPassword(password));
    }

    /// <summary>The team named <paramref name="name"/> when <paramref name="password"/> is its password, else null.</summary>
    public TeamRow? SignIn(string name, string password) =>
        Store.TeamByName(name) is { PasswordHash: { } hash } team && Secrets.CheckPassword(password, hash) ? team : null;

    /// <summary>On start: the submissions a stopped service was checking are checked again, in every ladder.</summary>
    public void RecheckInterrupted()
    {
        foreach (var core in Cores())
        {
            core.RecheckInterrupted();
        }
    }

    /// <summary>
    /// Plays one match of the next ladder in turn that has one to play (<see cref="LadderCore.PlayNext"/>):
    /// each call starts at the ladder after the one the previous call started at, so every ladder that
    /// is not paused gets its share of the workers. False when no ladder had a match to play.
    /// </summary>
    public bool PlayNext()
    {
        var cores = Cores();
        int start = (int)((uint)Interlocked.Increment(ref _turn) % (uint)cores.Count);
        for (int k = 0; k < cores.Count; k++)
        {
            if (cores[(start + k) % cores.Count].PlayNext())
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>A team name: 1 to 40 letters, digits, spaces, '-', '_' or '.', not starting or ending with a space.</summary>
    public static void CheckName(string name)
    {
        if (name.Length is 0 or > 40 || name.Trim() != name || !name.All(c => char.IsLetterOrDigit(c) || c is ' ' or '-' or '_' or '.'))
        {
            throw new LadderInputException($"name must be 1 to 40 letters, digits, spaces, '-', '_' or '.', got {MessageText.Quote(name)}");
        }
    }

    private void Touch() => Changed?.Invoke();

    /// <summary>Disposes of the store.</summary>
    public void Dispose() => Store.Dispose();
}
