using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Hosting;
using URWPGSim2D.Ladder.Play;
using URWPGSim2D.Ladder.Storage;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder;

/// <summary>
/// One ladder without its web front: its teams' submissions, matchmaking, playing one match, the
/// final round and the standings (<see cref="LadderService"/> keeps the service's ladders, teams and
/// organiser). Every change goes through the store in one transaction; a match's record is written
/// once, keyed by its id, so a service stopped at any moment and started again plays what it was
/// playing again from the same seed and loses or doubles nothing.
/// </summary>
internal sealed class LadderCore
{
    private readonly LadderSettings _settings;
    private readonly LadderMatchPlayer _player;
    private readonly object _matchmaking = new();
    private readonly object _standingsGate = new();
    private string? _standingsKey;
    private (Standings Standings, string Json)? _standings;
    private long _changes;

    private LadderCore(ILadderStore store, LadderSettings settings, LadderRow ladder)
    {
        Store = store;
        _settings = settings;
        Files = new LadderFiles(store, settings.DataDir);
        Item = ItemRegistry.Find(ladder.Item) ?? throw new LadderInputException($"the ladder's item {Engine.Messages.MessageText.Quote(ladder.Item)} is not an item of this program");
        LadderId = ladder.Id;
        Directory.CreateDirectory(SubmissionsFolder);
        Directory.CreateDirectory(ReplaysFolder);
        _player = new LadderMatchPlayer(Item, settings.HostSettings, settings.StrategyTimeoutMs, Math.Max(4, (2 * settings.Workers) + 2));
    }

    /// <summary>The core of <paramref name="ladder"/> over a store whose schema is up to date (the service's, or a worker process's, which only plays its matches).</summary>
    public static LadderCore Player(ILadderStore store, LadderSettings settings, LadderRow ladder) => new(store, settings, ladder);

    /// <summary>Where rows are kept (the service's; this core does not dispose of it).</summary>
    public ILadderStore Store { get; }

    /// <summary>Submissions' and matches' files: in the database, copied into the data folder when used.</summary>
    public LadderFiles Files { get; }

    /// <summary>The ladder's item.</summary>
    public CompetitionItem Item { get; }

    /// <summary>The ladder's id.</summary>
    public long LadderId { get; }

    /// <summary>Upload limits.</summary>
    public LadderLimits Limits => _settings.Limits;

    /// <summary>Matches this process plays at once.</summary>
    public int Workers => _settings.Workers;

    /// <summary>Told whenever something may give a worker a match of this ladder to play (a submission, a resume, a requeue, a final round).</summary>
    public event Action? Changed;

    /// <summary>The ladder's row now.</summary>
    public LadderRow Ladder => Store.Ladder(LadderId)!;

    /// <summary>Submissions' files: a copy of each submission's, in a folder of its own (<see cref="LadderFiles"/>).</summary>
    public string SubmissionsFolder => Files.SubmissionsFolder;

    /// <summary>Replay pages: copies of those in the database, and those being played.</summary>
    public string ReplaysFolder => Path.Combine(_settings.DataDir, "replays");

    /// <summary>The most submissions of one team to one ladder per UTC day (the organiser's setting, else the default limit).</summary>
    public static int SubmissionsPerDay(ILadderStore store, LadderLimits limits) =>
        store.Setting("submissions_per_day") is { } text && int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out int n) ? n : limits.SubmissionsPerDay;

    /// <summary>
    /// Takes a team's upload: checks the limits and the names, writes its files, compiles and checks
    /// it once (sources in the compiler's limited child process; none of its code runs) and returns
    /// the submission with its log (the compile errors as the command line prints them).
    /// </summary>
    public SubmissionRow Submit(TeamRow team, IReadOnlyList<UploadedFile> files)
    {
        if (team.House is not null)
        {
            throw new LadderInputException($"team {Engine.Messages.MessageText.Quote(team.Name)} is a house entrant ({team.House}); it takes no submissions");
        }

        try
        {
            Uploads.CheckLimits(files, Limits);
        }
        catch (UploadException e)
        {
            throw new LadderInputException(e.Message);
        }

        var today = DateTime.UtcNow.Date;
        int limit = SubmissionsPerDay(Store, Limits);
        if (Store.SubmissionsSince(team.Id, LadderId, today) >= limit)
        {
            throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"submission: the limit of {limit} submissions a day is reached; try again after 00:00 UTC"));
        }

        var row = Store.AddSubmission(team.Id, LadderId, "upload", DateTime.UtcNow);
        string folder = Path.GetFullPath(Path.Combine(SubmissionsFolder, row.Id.ToString(CultureInfo.InvariantCulture)));
        string kind, spec;
        try
        {
            (kind, spec) = Uploads.Write(files, folder, Limits);
        }
        catch (UploadException e)
        {
            Store.FinishSubmission(row.Id, ok: false, e.Message);
            throw new LadderInputException(e.Message);
        }

        spec = Files.Keep(row.Id, folder, spec);
        var (ok, log) = Check(team, row.Id, spec, Path.GetDirectoryName(spec)!);
        Store.FinishSubmission(row.Id, ok, log);
        Touch();
        return Store.Submission(row.Id)! with { Kind = kind };
    }

    /// <summary>On start: the ladder's submissions a stopped service was checking are checked again (or refused when their files were never whole).</summary>
    public void RecheckInterrupted()
    {
        foreach (var s in Store.Submissions(null).Where(s => s.State == SubmissionRow.Checking && s.LadderId == LadderId))
        {
            var team = Store.Teams().First(t => t.Id == s.TeamId);
            string spec = s.Path.Length == 0 ? string.Empty : Files.Spec(s);
            if (!File.Exists(spec) && !Directory.Exists(spec))
            {
                Store.FinishSubmission(s.Id, ok: false, "the upload was interrupted; submit again");
                continue;
            }

            var (ok, log) = Check(team, s.Id, spec, Path.GetDirectoryName(spec)!);
            Store.FinishSubmission(s.Id, ok, log);
        }
    }

    // Compiles and checks, once: the loader stays readied for the submission's matches.
    private (bool Ok, string Log) Check(TeamRow team, long id, string spec, string folder)
    {
        var log = new List<string>();
        try
        {
            StrategyResolver.Prepare(spec, line => log.Add(line), _settings.HostSettings);
        }
        catch (StrategyLoadException e)
        {
            log.AddRange(e.Lines);
            return (false, Relative(log, folder));
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            log.Add($"{e.GetType().Name}: {e.Message.ReplaceLineEndings(" ")}");
            return (false, Relative(log, folder));
        }

        var loader = _player.Loader(team.Id, id, new Entrant(team.Name, spec));
        if (loader.Errors[0] is { } error)
        {
            log.Add(error);
            return (false, Relative(log, folder));
        }

        log.Add("ok: compiled and checked; it plays from its next match");
        return (true, Relative(log, folder));
    }

    // The log without the server's folders: paths as the team's upload names them.
    private static string Relative(List<string> lines, string folder) =>
        string.Join('\n', lines.Select(l => l.Replace(folder + Path.DirectorySeparatorChar, string.Empty, StringComparison.Ordinal).Replace(folder, ".", StringComparison.Ordinal)));

    /// <summary>Pauses or resumes ranked play (matches already running finish).</summary>
    public void SetPaused(bool paused)
    {
        Store.SetPaused(LadderId, paused);
        Touch();
    }

    /// <summary>Puts a finished match of the ladder back in the queue: it is played again from its seed, its old record removed.</summary>
    public void Requeue(long match)
    {
        if (Store.Match(match)?.LadderId != LadderId || !Store.Requeue(match))
        {
            throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"match: {match} is not a finished match"));
        }

        Touch();
    }

    /// <summary>Per team, what plays for it in this ladder now: its house strategy (a house entrant of this ladder) or its newest working submission to it (absent: nothing).</summary>
    public Dictionary<long, (long Submission, string Spec)> Playing()
    {
        var playing = new Dictionary<long, (long, string)>();
        foreach (var team in Store.Teams())
        {
            if (team.House is { } house)
            {
                if (team.LadderId == LadderId)
                {
                    playing[team.Id] = (0, house);
                }
            }
            else if (Store.NewestWorking(team.Id, LadderId) is { } s)
            {
                playing[team.Id] = (s.Id, s.Path);
            }
        }

        return playing;
    }

    /// <summary>
    /// Queues the next ranked match when fewer than <paramref name="waiting"/> wait: the team with the
    /// fewest games (then the lowest id) against the team nearest in rating (then fewest games, lowest
    /// id); sides alternate with the match id. Null when paused, once the final round has started, when
    /// fewer than two teams can play, or when enough wait.
    /// </summary>
    public MatchRow? MakeMatch(int waiting)
    {
        lock (_matchmaking)
        {
            var ladder = Ladder;
            if (ladder.Paused || Store.FinalMatches(LadderId).Count > 0 || Store.Matches(LadderId, [MatchRow.Queued], waiting).Count >= waiting)
            {
                return null;
            }

            var playing = Playing();
            if (playing.Count < 2)
            {
                return null;
            }

            var games = Store.Games(LadderId);
            var ratings = Ratings();
            var teams = Store.Teams().Where(t => playing.ContainsKey(t.Id)).ToList();
            int Games(TeamRow t) => games.TryGetValue(t.Id, out int g) ? g : 0;
            double Rating(TeamRow t) => ratings.TryGetValue(t.Name, out double r) ? r : 0;
            var first = teams.OrderBy(Games).ThenBy(t => t.Id).First();
            var second = teams.Where(t => t.Id != first.Id)
                .OrderBy(t => Math.Abs(Rating(t) - Rating(first)) + (25.0 * Games(t) / Math.Max(1, Games(first) + 1)))
                .ThenBy(Games).ThenBy(t => t.Id).First();
            return Store.AddMatch(LadderId, [first.Id, second.Id], [playing[first.Id].Submission, playing[second.Id].Submission], final: false, id => ladder.FirstSeed + (ulong)id);
        }
    }

    /// <summary>Claims the next queued match (making one when none waits) and plays it; false when there was none to play.</summary>
    public bool PlayNext()
    {
        var match = Store.ClaimNext(LadderId);
        if (match is null)
        {
            MakeMatch(Math.Max(1, Workers));
            match = Store.ClaimNext(LadderId);
            if (match is null)
            {
                return false;
            }
        }

        Play(match);
        MakeMatch(Math.Max(1, Workers));
        return true;
    }

    /// <summary>Plays a claimed (running) match and writes its record once: true when this play's record was written (false: the match was written already, by another play of it).</summary>
    public bool Play(MatchRow match)
    {
        var teams = Store.Teams().ToDictionary(t => t.Id);
        var sides = new List<(long, long, Entrant)>();
        int[] order = match.Id % 2 == 0 ? [0, 1] : [1, 0]; // sides alternate with the id
        foreach (int k in order)
        {
            var team = teams[match.Teams[k]];
            long sub = match.Submissions[k];
            string spec = sub == 0 ? team.House ?? Entrant.Demo : Files.Spec(Store.Submission(sub)!);
            sides.Add((team.Id, sub, new Entrant(team.Name, spec)));
        }

        var ladder = Ladder;
        var output = new StrategyOutput(sides.Count);
        string replay = Files.PlayingReplay(match.Id);
        var record = _player.Play(checked((int)match.Id), match.Seed, ladder.Cycles, sides, replay, output);
        bool written = Files.Finish(match.Id, LadderMatchPlayer.Line(record), replay, MatchOutputs.Json([.. sides.Select((s, k) => (s.Item1, output.SlowestMs(k), output.Text(k)))]));
        Interlocked.Increment(ref _changes);
        return written;
    }

    /// <summary>
    /// Starts the final round: every pair of the <paramref name="top"/> teams ranked highest now (of those
    /// that can play) plays <paramref name="rounds"/> matches, each team with the submission it plays now;
    /// ranked play stops (the queued ranked matches are dropped, no more are made) and the standings are
    /// from then on those of the final round's matches alone. Sides alternate between a pair's matches.
    /// </summary>
    public FinalRound StartFinal(int top, int rounds)
    {
        if (top < 2 || top > 1000)
        {
            throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"top must be 2 to 1000, got {top}"));
        }

        if (rounds < 1 || rounds > 100)
        {
            throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"rounds must be 1 to 100, got {rounds}"));
        }

        lock (_matchmaking)
        {
            if (Store.FinalMatches(LadderId).Count > 0)
            {
                throw new LadderInputException("final: the final round has started already");
            }

            var playing = Playing();
            var byName = Store.Teams().ToDictionary(t => t.Name, StringComparer.Ordinal);
            var ranked = Standings().Standings.Rows.OrderBy(r => r.Rank)
                .Select(r => byName.TryGetValue(r.Name, out var t) ? t : null)
                .Where(t => t is not null && playing.ContainsKey(t.Id))
                .Select(t => t!)
                .ToList();
            if (ranked.Count < top)
            {
                throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"top: {ranked.Count} teams can play, fewer than {top}"));
            }

            var finalists = ranked.Take(top).ToList();
            var pairs = new List<(TeamRow A, TeamRow B)>();
            for (int i = 0; i < finalists.Count; i++)
            {
                for (int j = i + 1; j < finalists.Count; j++)
                {
                    pairs.Add((finalists[i], finalists[j]));
                }
            }

            // The matches get consecutive ids and Play swaps the sides of odd ids: with an even number of
            // pairs, a pair's id parity is the same every round, so its order is swapped every other round.
            var matches = new List<(long, long, long, long)>(pairs.Count * rounds);
            for (int r = 0; r < rounds; r++)
            {
                bool swap = pairs.Count % 2 == 0 && r % 2 == 1;
                foreach (var (a, b) in pairs)
                {
                    var (x, y) = swap ? (b, a) : (a, b);
                    matches.Add((x.Id, y.Id, playing[x.Id].Submission, playing[y.Id].Submission));
                }
            }

            var ladder = Ladder;
            if (!Store.StartFinal(LadderId, matches, id => ladder.FirstSeed + (ulong)id))
            {
                throw new LadderInputException("final: the final round has started already");
            }
        }

        Touch();
        return Final()!;
    }

    /// <summary>The final round (its teams, matches per pair, matches played and in all), or null before it starts.</summary>
    public FinalRound? Final() => FinalRound.Of(Store.FinalMatches(LadderId));

    /// <summary>
    /// The standings now (computed again only when a record or a team changed): of the ranked matches,
    /// or once the final round has started, of its matches alone (its teams, their submissions then),
    /// marked <c>"final": true</c> with the round's progress.
    /// </summary>
    public (Standings Standings, string Json) Standings()
    {
        var finalMatches = Store.FinalMatches(LadderId);
        var final = FinalRound.Of(finalMatches);
        IReadOnlyList<(long Id, string Record, bool Final)> records = final is null ? Store.Records(LadderId) : [.. finalMatches.Where(m => m.State == MatchRow.Done).Select(m => (m.Id, m.Record!, true))];
        var playing = Playing();
        var teams = Store.Teams();
        string key = (final is null ? "ranked|" : "final|") + string.Join(',', records.Select(r => r.Id.ToString(CultureInfo.InvariantCulture))) + "|" + string.Join(',', playing.Keys.Order().Select(k => k.ToString(CultureInfo.InvariantCulture)));
        lock (_standingsGate)
        {
            if (_standings is { } cached && _standingsKey == key)
            {
                return cached;
            }

            var parsed = records.Select(r => TournamentFile.ParseRecord(r.Record)).ToList();
            List<Entrant> entrants;
            if (final is null)
            {
                var names = new HashSet<string>(parsed.SelectMany(r => r.Entrants), StringComparer.Ordinal);
                entrants = [.. teams.Where(t => playing.ContainsKey(t.Id) || names.Contains(t.Name))
                    .Select(t => new Entrant(t.Name, playing.TryGetValue(t.Id, out var p) ? Spec(p.Submission, p.Spec) : "none"))];
            }
            else
            {
                entrants = [.. teams.Where(t => final.Teams.ContainsKey(t.Id)).Select(t => new Entrant(t.Name, Spec(final.Teams[t.Id], t.House ?? Entrant.Demo)))];
            }

            var ladder = Ladder;
            var header = new TournamentHeader(Item.Slug, entrants, 1, ladder.FirstSeed, ladder.Cycles, _settings.StrategyTimeoutMs, parsed.Count);
            // A ladder no team plays in yet (a new one) has empty standings.
            var standings = entrants.Count == 0 ? new Standings(header, Item.TeamCount, [], [], new (int W, int D, int L)[0, 0]) : Tournament.Standings.Compute(header, Item.TeamCount, parsed);
            string json = StandingsJson.Format(standings, id => Files.Has(id, LadderFiles.Replay));
            if (final is not null)
            {
                json = "{\n  \"final\": true,\n  \"finalRound\": " + string.Create(CultureInfo.InvariantCulture,
                    $"{{\"top\": {final.Teams.Count}, \"rounds\": {final.Rounds}, \"played\": {final.Played}, \"matches\": {final.Matches}}},\n") + json["{\n".Length..];
            }

            _standings = (standings, json);
            _standingsKey = key;
            return (standings, json);
        }

        static string Spec(long submission, string house) => submission == 0 ? house : "submission " + submission.ToString(CultureInfo.InvariantCulture);
    }

    /// <summary>Per team name, its rating in the last standings computed (none before the first).</summary>
    private Dictionary<string, double> Ratings()
    {
        (Standings Standings, string Json)? s;
        lock (_standingsGate)
        {
            s = _standings;
        }

        return s is null ? [] : s.Value.Standings.Rows.ToDictionary(r => r.Name, r => r.Rating, StringComparer.Ordinal);
    }

    private void Touch()
    {
        Interlocked.Increment(ref _changes);
        Changed?.Invoke();
    }
}
