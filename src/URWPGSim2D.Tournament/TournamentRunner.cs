using System.Threading;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Hosting;

namespace URWPGSim2D.Tournament;

/// <summary>
/// Plays a list of scheduled matches on several threads, each match alone on one thread, so a
/// match's result depends only on its seed and entrants. Each match gets fresh team strategies from
/// <paramref name="Entrants"/> (user strategies in fresh strategy hosts under <c>--isolation process</c>),
/// so their faults are charged to their teams and the match is played. A match with an entrant that
/// could not be loaded is not played: it becomes a forfeit record. A match that fails inside the server is
/// reported and recorded as a forfeit of the team at fault (<see cref="Failed"/>), which a re-run keeps;
/// the others go on. A remote entrant whose client does not come forfeits the match (not a failure: a
/// re-run plays it again).
/// </summary>
/// <param name="Item">The item.</param>
/// <param name="Header">The tournament.</param>
/// <param name="Entrants">The readied entrants (their load errors and team strategies).</param>
/// <param name="ReplayPage">Where match J's replay page goes, or null for no replays.</param>
public sealed record TournamentRunner(CompetitionItem Item, TournamentHeader Header, EntrantLoader Entrants, Func<int, string>? ReplayPage)
{
    /// <summary>
    /// Plays a match somewhere else and gives its result when it is over (the live page of
    /// <c>tournament --live</c>: one match after another, in real time); null to play each match here
    /// as fast as it goes. With one, the matches are played one at a time.
    /// </summary>
    public Func<ScheduledMatch, MatchSettings, MatchResult>? Player { get; init; }

    /// <summary>Plays the matches; <paramref name="finished"/> is called (under a lock) as each ends, with its record and, when it failed inside the server, the failure.</summary>
    /// <param name="matches">The matches to play.</param>
    /// <param name="threads">Matches at once, ≥ 1.</param>
    /// <param name="finished">Called once per match in the order they finish.</param>
    public void Run(IReadOnlyList<ScheduledMatch> matches, int threads, Action<ScheduledMatch, TournamentRecord?, string?> finished)
    {
        int next = -1;
        var gate = new object();

        void Work()
        {
            int position;
            while ((position = Interlocked.Increment(ref next)) < matches.Count)
            {
                var match = matches[position];
                TournamentRecord? record;
                string? failure = null;
                try
                {
                    record = PlayOne(match);
                }
                catch (TeamFaultException e) when (e.InnerException is RemoteWaitException)
                {
                    record = Failed(match, e) with { Failed = false }; // a remote entrant's client did not come: its forfeit, played again on a re-run
                }
                catch (Exception e) when (e is not OutOfMemoryException)
                {
                    record = Failed(match, e);
                    failure = record.Reasons[0];
                }

                lock (gate)
                {
                    finished(match, record, failure);
                }
            }
        }

        var pool = new Thread[Player is null ? Math.Clamp(threads, 1, Math.Max(1, matches.Count)) - 1 : 0];
        for (int w = 0; w < pool.Length; w++)
        {
            pool[w] = new Thread(Work) { IsBackground = true, Name = $"tournament worker {w + 1}" };
            pool[w].Start();
        }

        Work();
        foreach (var thread in pool)
        {
            thread.Join();
        }
    }

    /// <summary>
    /// The record of a match that failed inside the server: a forfeit of the team the failure was
    /// put on (<see cref="TeamFaultException"/>), else of every team of the match, with the reason.
    /// </summary>
    public TournamentRecord Failed(ScheduledMatch match, Exception e)
    {
        var names = new string[match.Sides.Count];
        for (int side = 0; side < names.Length; side++)
        {
            names[side] = Header.Entrants[match.Sides[side]].Name;
        }

        string why = StandingsText.Line(e is TeamFaultException { InnerException: RemoteWaitException w } ? w.Message : e is TeamFaultException t ? $"the match failed inside the server: {t.InnerException!.GetType().Name}: {t.InnerException.Message}" : $"the match failed inside the server: {e.GetType().Name}: {e.Message}");
        var teams = new List<int>();
        for (int side = 0; side < match.Sides.Count; side++)
        {
            if (e is not TeamFaultException f || f.Team == side)
            {
                teams.Add(side);
            }
        }

        if (teams.Count == 0)
        {
            teams.AddRange(Enumerable.Range(0, match.Sides.Count));
        }

        return new TournamentRecord(match.Index, match.Seed, names, null, teams, teams.ConvertAll(_ => why), Failed: true);
    }

    /// <summary>The record of one match: played, or forfeited by the entrants that cannot be loaded.</summary>
    public TournamentRecord PlayOne(ScheduledMatch match)
    {
        var names = new string[match.Sides.Count];
        var teams = new TeamStrategy?[Math.Max(2, match.Sides.Count)];
        var forfeits = new List<int>();
        var reasons = new List<string>();
        for (int t = 0; t < match.Sides.Count; t++)
        {
            var entrant = Header.Entrants[match.Sides[t]];
            names[t] = entrant.Name;
            string? error = Entrants.Errors[match.Sides[t]];
            if (error is null)
            {
                try
                {
                    teams[t] = Entrants.Create(match.Sides[t]);
                }
                catch (StrategyLoadException e)
                {
                    error = EntrantLoader.Reason(e); // loaded before, not now: forfeit this match
                }
            }

            if (error is not null)
            {
                forfeits.Add(t);
                reasons.Add(error);
            }
        }

        if (forfeits.Count > 0)
        {
            return new TournamentRecord(match.Index, match.Seed, names, null, forfeits, reasons);
        }

        var result = Player is { } player
            ? player(match, TournamentMatchPlayer.Settings(Item, match, teams, Header.Cycles, Header.StrategyTimeoutMs))
            : TournamentMatchPlayer.Play(Item, match, teams, Header.Cycles, Header.StrategyTimeoutMs, ReplayPage?.Invoke(match.Index));
        return new TournamentRecord(match.Index, match.Seed, names, result, [], []);
    }
}
