namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// Standings of an item of four teams: every match counts as a game between every two of its
/// sides (the higher score wins, equal scores draw, the item's winner beats the others, a side that
/// could not play loses to those that did), so all four sides are counted, not only teams 0 and 1.
/// </summary>
public sealed class MultiTeamStandingsTests
{
    private static readonly string[] Names = ["a", "b", "c", "d"];

    [Fact]
    public void EveryPairOfSidesIsOneGameAndTheScoresOrderTheEntrants()
    {
        // Four rotations per seed, two seeds: entrant a always scores 3, b 2, c 1, d 0, on every side.
        var records = new List<TournamentRecord>();
        int index = 0;
        for (int seed = 0; seed < 2; seed++)
        {
            for (int r = 0; r < 4; r++)
            {
                var sides = Enumerable.Range(0, 4).Select(t => Names[(r + t) % 4]).ToArray();
                int[] scores = sides.Select(n => 3 - System.Array.IndexOf(Names, n)).ToArray();
                records.Add(Played(index++, sides, scores, winner: -1));
            }
        }

        var s = Standings.Compute(Header(records.Count), 4, records, replicates: 200);
        Assert.Equal(Names, s.Rows.Select(r => r.Name).ToArray());

        // Each entrant meets the three others in each of the 8 matches: 24 games; a beats all of them.
        var expected = new (int W, int D, int L)[] { (24, 0, 0), (16, 0, 8), (8, 0, 16), (0, 0, 24) };
        for (int i = 0; i < 4; i++)
        {
            var row = s.Rows[i];
            Assert.Equal((24, expected[i].W, expected[i].D, expected[i].L), (row.Played, row.Wins, row.Draws, row.Losses));
        }

        Assert.Equal((8, 0, 0), s.Wdl[0, 1]);
        Assert.Equal((0, 0, 8), s.Wdl[3, 2]);
    }

    [Fact]
    public void EqualScoresDrawTheItemsWinnerWinsAndAForfeitLosesToThoseWhoPlayed()
    {
        var records = new List<TournamentRecord>
        {
            Played(0, Names, [0, 0, 0, 0], winner: -1),   // six draws
            Played(1, Names, [0, 0, 0, 0], winner: 2),    // c beats a, b and d; the others draw
            new(2, 2, Names, null, [3], ["d: no strategy class"]), // d loses to a, b and c; a, b and c did not play each other
        };

        var s = Standings.Compute(Header(records.Count), 4, records, replicates: 100);
        var row = s.Rows.ToDictionary(r => r.Name);
        Assert.Equal((7, 4, 3, 0), (row["c"].Played, row["c"].Wins, row["c"].Draws, row["c"].Losses));
        Assert.Equal((7, 1, 5, 1), (row["a"].Played, row["a"].Wins, row["a"].Draws, row["a"].Losses));
        Assert.Equal((9, 0, 5, 4), (row["d"].Played, row["d"].Wins, row["d"].Draws, row["d"].Losses));
        Assert.Equal("d: no strategy class", row["d"].Error);
        Assert.Equal("c", s.Rows[0].Name);
        Assert.Equal("d", s.Rows[^1].Name);
    }

    private static TournamentHeader Header(int matches) =>
        new("four-teams", Names.Select(n => new Entrant(n, "idle")).ToArray(), 2, 1, 100, 100, matches);

    private static TournamentRecord Played(int index, string[] sides, int[] scores, int winner) =>
        new(index, (ulong)index, sides, new MatchResult(index, (ulong)index, 100, scores[0], scores[1], new long[7], 0, 0, 0, 0f, 0, 0, "four-teams", scores, winner, "test"), [], []);
}
