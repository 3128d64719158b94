namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// The points table: 3 a win, 1 a draw; ties by goal difference, goals, head to head, name. Small
/// leagues worked out by hand, and random leagues against the table's invariants.
/// </summary>
public sealed class PointsTableTests
{
    [Fact]
    public void Head_to_head_separates_entrants_equal_on_points_difference_and_goals()
    {
        string[] names = ["alpha", "beta", "gamma", "delta"];
        var records = new List<TournamentRecord>
        {
            Played(0, "alpha", "beta", 0, 1),
            Played(1, "alpha", "gamma", 1, 0),
            Played(2, "beta", "gamma", 0, 1),
            Played(3, "alpha", "delta", 2, 1),
            Played(4, "beta", "delta", 2, 1),
            Played(5, "gamma", "delta", 0, 1),
        };

        var table = PointsTable.Compute(records, names);

        // alpha and beta: 6 points, +1, 3 goals each; beta beat alpha. gamma and delta: 3 points, -1; delta scored 3, gamma 1.
        Assert.Equal(["beta", "alpha", "delta", "gamma"], table.Select(r => r.Name).ToArray());
        Assert.Equal(new PointsRow(1, "beta", 1, 3, 2, 0, 1, 3, 2, 6), table[0]);
        Assert.Equal(new PointsRow(0, "alpha", 2, 3, 2, 0, 1, 3, 2, 6), table[1]);
        Assert.Equal(new PointsRow(3, "delta", 3, 3, 1, 0, 2, 3, 4, 3), table[2]);
        Assert.Equal(new PointsRow(2, "gamma", 4, 3, 1, 0, 2, 1, 2, 3), table[3]);
        Assert.Equal(-1, table[2].GoalDifference);
    }

    [Fact]
    public void Goal_difference_comes_before_the_name_and_a_draw_is_one_point()
    {
        string[] names = ["a", "b", "z"];
        var records = new List<TournamentRecord>
        {
            Played(0, "a", "z", 1, 0),
            Played(1, "b", "z", 3, 0),
            Played(2, "a", "b", 0, 0),
        };

        var table = PointsTable.Compute(records, names);
        Assert.Equal(["b", "a", "z"], table.Select(r => r.Name).ToArray());
        Assert.Equal((4, 3, 1, 0, 1), (table[0].Points, table[0].GoalsFor, table[0].Won, table[0].Lost, table[0].Drawn));
        Assert.Equal((4, 1), (table[1].Points, table[1].GoalDifference));
        Assert.Equal((0, 0, 4), (table[2].Points, table[2].GoalsFor, table[2].GoalsAgainst));
    }

    [Fact]
    public void A_forfeit_is_a_win_without_goals_for_the_side_that_could_play()
    {
        string[] names = ["a", "b"];
        var records = new List<TournamentRecord>
        {
            new(0, 0, ["a", "b"], null, [1], ["b: no strategy class"]),
            Played(1, "b", "a", 2, 2),
        };

        var table = PointsTable.Compute(records, names);
        Assert.Equal(new PointsRow(0, "a", 1, 2, 1, 1, 0, 2, 2, 4), table[0]);
        Assert.Equal(new PointsRow(1, "b", 2, 2, 0, 1, 1, 2, 2, 1), table[1]);
    }

    [Fact]
    public void Random_leagues_keep_the_tables_invariants()
    {
        var random = new Random(41);
        for (int round = 0; round < 100; round++)
        {
            int n = random.Next(2, 7);
            string[] names = Enumerable.Range(0, n).Select(i => "e" + i).ToArray();
            var records = new List<TournamentRecord>();
            for (int m = 0; m < 30; m++)
            {
                int a = random.Next(n), b = (a + 1 + random.Next(n - 1)) % n;
                records.Add(Played(m, names[a], names[b], random.Next(4), random.Next(4)));
            }

            var table = PointsTable.Compute(records, names);
            Assert.Equal(names.OrderBy(x => x, StringComparer.Ordinal), table.Select(r => r.Name).OrderBy(x => x, StringComparer.Ordinal));
            Assert.Equal(Enumerable.Range(1, n), table.Select(r => r.Rank));
            Assert.Equal(table.Sum(r => r.GoalsFor), table.Sum(r => r.GoalsAgainst));
            Assert.Equal(table.Sum(r => r.Won), table.Sum(r => r.Lost));
            Assert.Equal(2 * records.Count, table.Sum(r => r.Played));
            foreach (var r in table)
            {
                Assert.Equal((3 * r.Won) + r.Drawn, r.Points);
                Assert.Equal(r.Played, r.Won + r.Drawn + r.Lost);
            }

            for (int k = 1; k < n; k++)
            {
                var (x, y) = (table[k - 1], table[k]);
                Assert.True((x.Points, x.GoalDifference, x.GoalsFor).CompareTo((y.Points, y.GoalDifference, y.GoalsFor)) >= 0, $"{x} before {y}");
            }
        }
    }

    [Fact]
    public void Places_follow_points_then_goal_difference_then_goals_in_every_view()
    {
        string[] names = ["a", "b", "c"];
        var s = Standings.Compute(Header(names), 2,
        [
            Played(0, "a", "b", 3, 0), Played(1, "b", "a", 1, 1),
            Played(2, "a", "c", 0, 2), Played(3, "c", "a", 0, 0),
            Played(4, "b", "c", 2, 1), Played(5, "c", "b", 1, 0),
        ], replicates: 50);
        Assert.Equal(["c", "a", "b"], s.Points.Select(p => p.Name));
        Assert.Equal((4, 2, 1, 1, 4, 2, 7), Of(s.Points[0]));
        Assert.Equal((4, 1, 2, 1, 4, 3, 5), Of(s.Points[1]));
        Assert.Equal((4, 1, 1, 2, 3, 6, 4), Of(s.Points[2]));

        Assert.Contains("| 1 | c | 4 | 2 | 1 | 1 | 4 | 2 | +2 | 7 |\n| 2 | a | 4 | 1 | 2 | 1 | 4 | 3 | +1 | 5 |\n| 3 | b | 4 | 1 | 1 | 2 | 3 | 6 | -3 | 4 |\n", StandingsMarkdown.Format(s), StringComparison.Ordinal);
        Assert.Contains("<h2>Points table</h2>", ReportPage.Format(s, _ => false), StringComparison.Ordinal);
        Assert.Contains("\"points\": [\n    {\"name\": \"c\", \"rank\": 1, \"played\": 4, \"won\": 2, \"drawn\": 1, \"lost\": 1, \"goalsFor\": 4, \"goalsAgainst\": 2, \"goalDifference\": 2, \"points\": 7},", StandingsJson.Format(s), StringComparison.Ordinal);
    }

    [Fact]
    public void A_one_team_item_has_no_points_table()
    {
        var s = Standings.Compute(new TournamentHeader("transport", [new Entrant("a", "idle")], 1, 1, 100, 100, 1), 1, [], replicates: 10);
        Assert.Empty(s.Points);
        Assert.DoesNotContain("\"points\"", StandingsJson.Format(s), StringComparison.Ordinal);
        Assert.DoesNotContain("Points table", StandingsMarkdown.Format(s), StringComparison.Ordinal);
    }

    private static (int, int, int, int, int, int, int) Of(PointsRow p) => (p.Played, p.Won, p.Drawn, p.Lost, p.GoalsFor, p.GoalsAgainst, p.Points);

    private static TournamentHeader Header(string[] names) =>
        new("ball-grab", names.Select(n => new Entrant(n, "idle")).ToArray(), 1, 1, 100, 100, names.Length * (names.Length - 1));

    // A two-team match: the higher score wins (the item's rule in these tests), equal scores draw.
    internal static TournamentRecord Played(int index, string team0, string team1, int score0, int score1) =>
        new(index, (ulong)index, [team0, team1], new MatchResult(index, (ulong)index, 100, score0, score1, new long[7], 0, 0, 0, 0f, 0, 0, "ball-grab", [score0, score1], score0 > score1 ? 0 : score1 > score0 ? 1 : -1, "test"), [], []);
}
