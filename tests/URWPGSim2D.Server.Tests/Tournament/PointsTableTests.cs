using System.Linq;
using URWPGSim2D.Server.Batch;
using URWPGSim2D.Server.Tournament;
using Xunit;

namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// The points table of a two-team tournament: 3 a win, 1 a draw, 0 a loss (a forfeit a loss without
/// goals); places by points, goal difference, goals, then head to head, then the name; in
/// standings.md and report.html.
/// </summary>
public sealed class PointsTableTests
{
    private static readonly string[] Names = ["a", "b", "c", "d"];

    [Fact]
    public void Places_follow_points_then_goal_difference_then_goals()
    {
        var s = Standings.Compute(Header(3), 2,
        [
            Played(0, "a", "b", 3, 0, 0), Played(1, "b", "a", 1, 1, -1),
            Played(2, "a", "c", 0, 2, 1), Played(3, "c", "a", 0, 0, -1),
            Played(4, "b", "c", 2, 1, 0), Played(5, "c", "b", 1, 0, 0),
        ]);
        var table = PointsTable.Of(s);
        Assert.Equal(["c", "a", "b"], table.Select(p => p.Name));
        Assert.Equal((4, 2, 1, 1, 4, 2, 7), Of(table[0]));
        Assert.Equal((4, 1, 2, 1, 4, 3, 5), Of(table[1]));
        Assert.Equal((4, 1, 1, 2, 3, 6, 4), Of(table[2]));

        string md = StandingsMarkdown.Format(s);
        Assert.Contains("| Place | Entrant | Played | Wins | Draws | Losses | Goals | Difference | Points |\n|---:|---|---:|---:|---:|---:|---|---:|---:|\n| 1 | c | 4 | 2 | 1 | 1 | 4:2 | +2 | 7 |\n| 2 | a | 4 | 1 | 2 | 1 | 4:3 | +1 | 5 |\n| 3 | b | 4 | 1 | 1 | 2 | 3:6 | -3 | 4 |\n", md, System.StringComparison.Ordinal);
        Assert.Contains("<h2>Points table</h2>", ReportPage.Format(s, _ => false), System.StringComparison.Ordinal);
    }

    [Fact]
    public void Entrants_level_on_points_difference_and_goals_are_placed_by_their_matches_against_each_other()
    {
        // a and b: a win, a draw and a loss each, 1:1 in goals; b beat a and drew with it.
        var s = Standings.Compute(Header(4), 2,
        [
            Played(0, "a", "b", 0, 1, 1), Played(1, "b", "a", 0, 0, -1),
            Played(2, "a", "d", 1, 0, 0), Played(3, "d", "b", 1, 0, 0),
        ]);
        var table = PointsTable.Of(s);
        var a = table.Single(p => p.Name == "a");
        var b = table.Single(p => p.Name == "b");
        Assert.Equal((a.Points, a.Difference, a.GoalsFor), (b.Points, b.Difference, b.GoalsFor)); // 4 points, 0, 1 each
        Assert.True(b.Rank < a.Rank, "b beat a and drew: it goes first");
    }

    [Fact]
    public void A_forfeit_is_a_loss_without_goals_and_other_items_have_no_table()
    {
        var forfeit = new TournamentRecord(0, 1, ["a", "b"], null, [1], ["cannot compile"]);
        var table = PointsTable.Of(Standings.Compute(Header(2), 2, [forfeit]));
        Assert.Equal((1, 1, 0, 0, 0, 0, 3), Of(table.Single(p => p.Name == "a")));
        Assert.Equal((1, 0, 0, 1, 0, 0, 0), Of(table.Single(p => p.Name == "b")));
        Assert.Empty(PointsTable.Of(Standings.Compute(new TournamentHeader("transport", [new Entrant("a", "idle")], 1, 1, 100, 100, 1), 1, [])));
    }

    private static (int, int, int, int, int, int, int) Of(PointsTable.Line p) => (p.Played, p.Wins, p.Draws, p.Losses, p.GoalsFor, p.GoalsAgainst, p.Points);

    private static TournamentHeader Header(int entrants) =>
        new("ball-grab", Names.Take(entrants).Select(n => new Entrant(n, "idle")).ToArray(), 1, 1, 100, 100, entrants * (entrants - 1));

    private static TournamentRecord Played(int index, string home, string away, int s0, int s1, int winner) =>
        new(index, 1, [home, away], new MatchResult(index, 1, 100, s0, s1, new long[7], 0, 0, 0, 0f, 0, 0, "ball-grab", [s0, s1], winner, "test"), [], []);
}
