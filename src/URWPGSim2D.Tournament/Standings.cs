namespace URWPGSim2D.Tournament;

/// <summary>
/// The standings of a tournament, computed from its records alone (so a tournament and the merge
/// of its shards give the same standings): for an item of two or more teams the <see cref="PairRatings"/>
/// over every pair of sides of each match, for a one-team item the <see cref="ScoreRatings"/>; ranks follow the rating (two-team) or the mean
/// score, then the shorter mean match (one-team), then the name; each line names the other ranks
/// whose interval overlaps its own (their order is not settled by the results).
/// </summary>
/// <param name="Header">The tournament.</param>
/// <param name="Teams">Teams per match of its item.</param>
/// <param name="Records">Its records (one per scheduled match at most, any order).</param>
/// <param name="Rows">The lines, by rank.</param>
/// <param name="Wdl">Items of two or more teams: [i, j] = (wins, draws, losses) of entrant i against j, all sides together.</param>
public sealed record Standings(
    TournamentHeader Header, int Teams, IReadOnlyList<TournamentRecord> Records, IReadOnlyList<StandingsRow> Rows, (int W, int D, int L)[,] Wdl)
{
    /// <summary>Computes the standings.</summary>
    /// <param name="header">The tournament.</param>
    /// <param name="teams">Teams per match (1, 2 or 4).</param>
    /// <param name="records">Its records.</param>
    /// <param name="errors">Per entrant, why it could not be loaded in this run, or null (then the reason its forfeit records give).</param>
    /// <param name="replicates">Bootstrap replicates.</param>
    public static Standings Compute(TournamentHeader header, int teams, IEnumerable<TournamentRecord> records, IReadOnlyList<string?>? errors = null, int replicates = PairRatings.Replicates)
    {
        var sorted = records.OrderBy(r => r.Index).ToList();
        int n = header.Entrants.Count;
        var index = new Dictionary<string, int>(StringComparer.Ordinal);
        for (int i = 0; i < n; i++)
        {
            index[header.Entrants[i].Name] = i;
        }

        var error = new string?[n];
        for (int i = 0; i < n && errors is not null; i++)
        {
            error[i] = errors[i]; // this run's reason first: the freshest
        }

        foreach (var r in sorted)
        {
            for (int k = 0; k < r.Forfeits.Count; k++)
            {
                int e = index[r.Entrants[r.Forfeits[k]]];
                error[e] ??= r.Reasons[k];
            }
        }

        var rows = teams == 1 ? OneTeam(header, sorted, index, error, replicates, out var wdl) : Versus(sorted, header.Entrants.Select(e => e.Name).ToArray(), index, error, replicates, out wdl);
        var faults = Faults(sorted, index, n);
        rows = [.. rows.Select(r => r with { Faults = faults[r.Entrant] })];
        return new Standings(header, teams, sorted, Ranked(rows, teams), wdl)
        {
            Points = teams == 1 ? [] : PointsTable.Compute(sorted, [.. header.Entrants.Select(e => e.Name)]),
        };
    }

    /// <summary>Items of two or more teams: the points table (<see cref="PointsTable"/>), best first; empty for a one-team item.</summary>
    public IReadOnlyList<PointsRow> Points { get; init; } = [];

    /// <summary>With <c>--format groups-knockout</c>: the groups' tables and the bracket (<see cref="GroupsKnockout"/>); null for a round robin.</summary>
    public Bracket? Cup { get; init; }

    /// <summary>Whether any entrant had a runtime fault.</summary>
    public bool AnyFaults => Rows.Any(r => r.Faults is not null);

    // Per entrant, the runtime faults of its strategy over its matches (null: none), from the results' faults entries.
    private static EntrantFaults?[] Faults(List<TournamentRecord> records, Dictionary<string, int> index, int n)
    {
        var faults = new EntrantFaults?[n];
        var lastMatch = new int[n];
        foreach (var r in records)
        {
            foreach (var f in r.Result?.Faults ?? [])
            {
                if (f.Team < 0 || f.Team >= r.Entrants.Count || !index.TryGetValue(r.Entrants[f.Team], out int e))
                {
                    continue;
                }

                bool newMatch = faults[e] is null || lastMatch[e] != r.Index;
                faults[e] = EntrantFaults.Add(faults[e], r.Index, f, newMatch);
                lastMatch[e] = r.Index;
            }
        }

        return faults;
    }

    // Sorted by rank; each row told which others overlap it.
    private static List<StandingsRow> Ranked(List<StandingsRow> rows, int teams)
    {
        var order = rows
            .OrderByDescending(r => r.Rating)
            .ThenBy(r => teams == 1 ? r.Seconds : 0)
            .ThenBy(r => r.Name, StringComparer.Ordinal)
            .ToList();
        var ranked = new List<StandingsRow>(order.Count);
        for (int k = 0; k < order.Count; k++)
        {
            var overlapping = new List<int>();
            for (int m = 0; m < order.Count; m++)
            {
                if (m != k && order[m].Interval.Overlaps(order[k].Interval))
                {
                    overlapping.Add(m + 1);
                }
            }

            ranked.Add(order[k] with { Rank = k + 1, Overlapping = overlapping });
        }

        return ranked;
    }

    private static List<StandingsRow> Versus(List<TournamentRecord> records, string[] names, Dictionary<string, int> index, string?[] error, int replicates, out (int W, int D, int L)[,] wdl)
    {
        int n = names.Length;
        var games = new List<Game>(records.Count);
        var table = new (int W, int D, int L)[n, n];
        foreach (var r in records)
        {
            // Every pair of sides of the match is one game (two teams: the match itself).
            for (int p = 0; p < r.Entrants.Count; p++)
            {
                for (int q = p + 1; q < r.Entrants.Count; q++)
                {
                    if (Outcome(r, p, q) is not { } score)
                    {
                        continue; // both forfeit, or neither played: not a game
                    }

                    int a = index[r.Entrants[p]], b = index[r.Entrants[q]];
                    games.Add(new Game(a, b, score));
                    Count(table, a, b, score);
                    Count(table, b, a, 1 - score);
                }
            }
        }

        wdl = table;
        var (ratings, intervals) = PairRatings.Compute(n, games, replicates);
        var rows = new List<StandingsRow>(n);
        for (int i = 0; i < n; i++)
        {
            int w = 0, d = 0, l = 0;
            for (int j = 0; j < n; j++)
            {
                w += table[i, j].W;
                d += table[i, j].D;
                l += table[i, j].L;
            }

            rows.Add(new StandingsRow(i, names[i], 0, ratings[i], intervals[i], w + d + l, w, d, l, 0, error[i], []));
        }

        return rows;
    }

    /// <summary>
    /// Side <paramref name="p"/> against side <paramref name="q"/> of a match: 1 (p won), 0.5 (draw),
    /// 0 (q won), or null (no game). The item's winner beats every other side; otherwise, with more
    /// than two sides, the higher score wins; a side that could not play loses to one that did.
    /// </summary>
    public static double? Outcome(TournamentRecord r, int p, int q)
    {
        if (r.Result is { } result)
        {
            return result.Winner == p ? 1
                : result.Winner == q ? 0
                : r.Entrants.Count > 2 && result.Winner < 0 && result.Scores is { } s && s.Length > Math.Max(p, q) ? (s[p] > s[q] ? 1 : s[p] < s[q] ? 0 : 0.5)
                : 0.5;
        }

        bool pOut = r.Forfeits.Contains(p), qOut = r.Forfeits.Contains(q);
        return pOut == qOut ? null : pOut ? 0 : 1;
    }

    private static void Count((int W, int D, int L)[,] table, int i, int j, double score)
    {
        var c = table[i, j];
        table[i, j] = score == 1 ? (c.W + 1, c.D, c.L) : score == 0 ? (c.W, c.D, c.L + 1) : (c.W, c.D + 1, c.L);
    }

    private static List<StandingsRow> OneTeam(TournamentHeader header, List<TournamentRecord> records, Dictionary<string, int> index, string?[] error, int replicates, out (int W, int D, int L)[,] wdl)
    {
        int n = header.Entrants.Count;
        var matches = new List<(double, int)>[n];
        for (int i = 0; i < n; i++)
        {
            matches[i] = [];
        }

        foreach (var r in records)
        {
            int e = index[r.Entrants[0]];
            matches[e].Add(r.Result is { } result ? (result.Scores is { Length: > 0 } s ? s[0] : result.Goals0, result.Cycles) : (0, header.Cycles));
        }

        wdl = new (int, int, int)[0, 0];
        var random = new SplitMix64(PairRatings.Seed);
        var rows = new List<StandingsRow>(n);
        for (int i = 0; i < n; i++)
        {
            var (score, interval, cycles) = matches[i].Count == 0
                ? (0, new Interval(0, 0), 0)
                : ScoreRatings.Compute(matches[i], ref random, replicates);
            rows.Add(new StandingsRow(i, header.Entrants[i].Name, 0, score, interval, matches[i].Count, 0, 0, 0, cycles / 10, error[i], []));
        }

        return rows;
    }
}
