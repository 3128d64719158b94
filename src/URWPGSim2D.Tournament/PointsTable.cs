namespace URWPGSim2D.Tournament;

/// <summary>
/// The round robin's points table beside the ratings, as a class or a national contest ranks a league:
/// 3 points a win, 1 a draw, 0 a loss; ties broken by goal difference, then goals scored, then the
/// points of the games between the tied entrants alone (head to head), then the name. Every two sides
/// of a match are one game (<see cref="Standings.Outcome"/> decides it: the item's winner, with its tie
/// rules); the goals are each side's score in the match (the item's score where it has one). A forfeit
/// is a game the side that could play wins, with no goals.
/// </summary>
internal static class PointsTable
{
    /// <summary>Points for a win.</summary>
    public const int Win = 3;

    /// <summary>Points for a draw.</summary>
    public const int Draw = 1;

    /// <summary>The table, best first.</summary>
    /// <param name="records">The tournament's records.</param>
    /// <param name="names">The entrants' names, by entrant index.</param>
    public static IReadOnlyList<PointsRow> Compute(IReadOnlyList<TournamentRecord> records, IReadOnlyList<string> names)
    {
        int n = names.Count;
        var index = new Dictionary<string, int>(StringComparer.Ordinal);
        for (int i = 0; i < n; i++)
        {
            index[names[i]] = i;
        }

        var rows = new Tally[n];
        var games = new List<(int A, int B, double ScoreA)>();
        foreach (var r in records)
        {
            for (int p = 0; p < r.Entrants.Count; p++)
            {
                for (int q = p + 1; q < r.Entrants.Count; q++)
                {
                    if (Standings.Outcome(r, p, q) is not { } score || !index.TryGetValue(r.Entrants[p], out int a) || !index.TryGetValue(r.Entrants[q], out int b))
                    {
                        continue;
                    }

                    int goalsA = Goals(r, p), goalsB = Goals(r, q);
                    rows[a].Add(score, goalsA, goalsB);
                    rows[b].Add(1 - score, goalsB, goalsA);
                    games.Add((a, b, score));
                }
            }
        }

        var order = Enumerable.Range(0, n).ToList();
        order.Sort((x, y) => Compare(rows[x], rows[y]));

        // Runs of entrants equal on points, goal difference and goals: ordered by their games among themselves, then by name.
        var ranked = new List<int>(n);
        for (int start = 0; start < n;)
        {
            int end = start + 1;
            while (end < n && Compare(rows[order[start]], rows[order[end]]) == 0)
            {
                end++;
            }

            var tied = order.GetRange(start, end - start);
            if (tied.Count > 1)
            {
                var among = HeadToHead(tied, games);
                tied.Sort((x, y) => among[y] != among[x] ? among[y].CompareTo(among[x]) : string.CompareOrdinal(names[x], names[y]));
            }

            ranked.AddRange(tied);
            start = end;
        }

        var table = new List<PointsRow>(n);
        for (int k = 0; k < n; k++)
        {
            int e = ranked[k];
            var t = rows[e];
            table.Add(new PointsRow(e, names[e], k + 1, t.Won + t.Drawn + t.Lost, t.Won, t.Drawn, t.Lost, t.For, t.Against, t.Points));
        }

        return table;
    }

    // A side's goals in a match: its item score where the item keeps one, else the goals; none in a forfeit.
    private static int Goals(TournamentRecord r, int side) => r.Result switch
    {
        null => 0,
        { Scores: { } s } when side < s.Length => s[side],
        { } result => side == 0 ? result.Goals0 : side == 1 ? result.Goals1 : 0,
    };

    // Better first: more points, then a larger goal difference, then more goals.
    private static int Compare(Tally x, Tally y) =>
        x.Points != y.Points ? y.Points.CompareTo(x.Points)
        : x.For - x.Against != y.For - y.Against ? (y.For - y.Against).CompareTo(x.For - x.Against)
        : y.For.CompareTo(x.For);

    // Points of each tied entrant in the games between tied entrants only.
    private static Dictionary<int, int> HeadToHead(List<int> tied, List<(int A, int B, double ScoreA)> games)
    {
        var points = tied.ToDictionary(e => e, _ => 0);
        foreach (var (a, b, score) in games)
        {
            if (points.ContainsKey(a) && points.ContainsKey(b))
            {
                points[a] += PointsFor(score);
                points[b] += PointsFor(1 - score);
            }
        }

        return points;
    }

    private static int PointsFor(double score) => score == 1 ? Win : score == 0 ? 0 : Draw;

    private struct Tally
    {
        public int Won;
        public int Drawn;
        public int Lost;
        public int For;
        public int Against;

        public readonly int Points => (Won * Win) + (Drawn * Draw);

        public void Add(double score, int goalsFor, int goalsAgainst)
        {
            if (score == 1)
            {
                Won++;
            }
            else if (score == 0)
            {
                Lost++;
            }
            else
            {
                Drawn++;
            }

            For += goalsFor;
            Against += goalsAgainst;
        }
    }
}

/// <summary>One entrant's line of the points table.</summary>
/// <param name="Entrant">Its index.</param>
/// <param name="Name">Its name.</param>
/// <param name="Rank">Its place in the table, from 1.</param>
/// <param name="Played">Games played (every two sides of a match are one game).</param>
/// <param name="Won">Games won.</param>
/// <param name="Drawn">Games drawn.</param>
/// <param name="Lost">Games lost.</param>
/// <param name="GoalsFor">Goals scored.</param>
/// <param name="GoalsAgainst">Goals conceded.</param>
/// <param name="Points">Points: 3 a win, 1 a draw.</param>
public sealed record PointsRow(int Entrant, string Name, int Rank, int Played, int Won, int Drawn, int Lost, int GoalsFor, int GoalsAgainst, int Points)
{
    /// <summary>Goals scored less goals conceded.</summary>
    public int GoalDifference => GoalsFor - GoalsAgainst;
}
