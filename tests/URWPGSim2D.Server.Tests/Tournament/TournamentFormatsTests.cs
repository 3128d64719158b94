namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// The points table and the spreadsheet files of a real tournament: standings.json's points,
/// standings.md's and report.html's tables, standings.csv and matches.csv, the points recounted
/// from matches.csv alone; and the CSV writer's quoting of hostile names.
/// </summary>
public sealed class TournamentFormatsTests() : TempFolderTest("urwpg-formats-")
{
    [Fact]
    public void Every_view_has_the_points_table_and_the_csv_files_agree_with_the_matches()
    {
        string dir = Path.Combine(Folder, "t");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "chaser=chase-ball", "--entrant", "still=idle", "--seeds", "1", "--seed", "6", "--cycles", "600", "--out", dir);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("points table (3 points a win, 1 a draw; ties: goal difference, goals scored, head to head, name):\n", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("wrote results.jsonl, standings.json, standings.md, standings.csv, matches.csv and report.html in " + dir, run.Stdout, StringComparison.Ordinal);

        // The points recounted from matches.csv alone.
        string[] matches = ReadCsv(Path.Combine(dir, "matches.csv"));
        Assert.Equal("match,seed,team_0,team_1,score_0,score_1,winner,result,forfeited", matches[0]);
        Assert.Equal(7, matches.Length); // 3 entrants, both sides: 6 matches
        var recount = new Dictionary<string, (int Points, int For, int Against)>();
        foreach (string line in matches.Skip(1))
        {
            string[] f = line.Split(',');
            string a = f[2], b = f[3], winner = f[6];
            int ga = int.Parse(f[4], System.Globalization.CultureInfo.InvariantCulture), gb = int.Parse(f[5], System.Globalization.CultureInfo.InvariantCulture);
            Add(recount, a, winner == a ? 3 : winner == b ? 0 : 1, ga, gb);
            Add(recount, b, winner == b ? 3 : winner == a ? 0 : 1, gb, ga);
        }

        using var json = JsonDocument.Parse(File.ReadAllText(Path.Combine(dir, "standings.json")));
        var points = json.RootElement.GetProperty("points").EnumerateArray().ToList();
        Assert.Equal(3, points.Count);
        foreach (var p in points)
        {
            var (pts, gf, ga) = recount[p.GetProperty("name").GetString()!];
            Assert.Equal((pts, gf, ga, gf - ga), (p.GetProperty("points").GetInt32(), p.GetProperty("goalsFor").GetInt32(), p.GetProperty("goalsAgainst").GetInt32(), p.GetProperty("goalDifference").GetInt32()));
        }

        Assert.Equal(points.Select(p => p.GetProperty("points").GetInt32()).OrderByDescending(x => x), points.Select(p => p.GetProperty("points").GetInt32()));

        // standings.csv: one line per entrant, its points as in standings.json.
        string[] standings = ReadCsv(Path.Combine(dir, "standings.csv"));
        Assert.Equal("rank,entrant,rating,ci_low,ci_high,played,wins,draws,losses,points_rank,points,goals_for,goals_against,goal_difference,exceptions,timeouts,bad_answers,host_ends,error", standings[0]);
        Assert.Equal(4, standings.Length);
        foreach (string line in standings.Skip(1))
        {
            string[] f = line.Split(',');
            var p = points.Single(x => x.GetProperty("name").GetString() == f[1]);
            Assert.Equal(p.GetProperty("rank").GetInt32().ToString(System.Globalization.CultureInfo.InvariantCulture), f[9]);
            Assert.Equal(p.GetProperty("points").GetInt32().ToString(System.Globalization.CultureInfo.InvariantCulture), f[10]);
        }

        string md = File.ReadAllText(Path.Combine(dir, "standings.md"));
        Assert.Contains("| Rank | Entrant | Played | Won | Drawn | Lost | Goals for | Goals against | Goal difference | Points |", md, StringComparison.Ordinal);
        string html = File.ReadAllText(Path.Combine(dir, "report.html"));
        Assert.Contains("<h2>Points table</h2>", html, StringComparison.Ordinal);
        Assert.Contains("<th>Goal difference</th><th>Points</th>", html, StringComparison.Ordinal);
    }

    [Fact]
    public void Csv_fields_are_quoted_and_never_formulas()
    {
        string[] names = ["=HYPERLINK(\"x\")", "a,b", "plain"];
        var header = new TournamentHeader("ball-grab", names.Select(n => new Entrant(n, "idle")).ToArray(), 1, 1, 100, 100, 2);
        var records = new List<TournamentRecord>
        {
            PointsTableTests.Played(0, names[0], names[1], 1, 0),
            new(1, 1, [names[1], names[2]], null, [0], ["a,b: cannot read \"x\"\nsecond line"]),
        };
        var s = Standings.Compute(header, 2, records, replicates: 50);

        string standings = StandingsCsv.Standings(s);
        Assert.StartsWith("\uFEFFrank,entrant,", standings, StringComparison.Ordinal);
        Assert.Contains("\"'=HYPERLINK(\"\"x\"\")\"", standings, StringComparison.Ordinal);
        Assert.Contains(",\"a,b\",", standings, StringComparison.Ordinal);
        Assert.Contains("\"a,b: cannot read \"\"x\"\" second line\"", standings, StringComparison.Ordinal);

        string matches = StandingsCsv.Matches(s);
        string[] lines = matches.TrimStart('\uFEFF').Split("\r\n");
        Assert.Equal("0,0,\"'=HYPERLINK(\"\"x\"\")\",\"a,b\",1,0,\"'=HYPERLINK(\"\"x\"\")\",test,", lines[1]);
        Assert.Equal("1,1,\"a,b\",plain,,,,forfeit,\"a,b\"", lines[2]);
        Assert.Equal(string.Empty, lines[3]);
    }

    private static void Add(Dictionary<string, (int Points, int For, int Against)> table, string name, int points, int goalsFor, int goalsAgainst)
    {
        var t = table.GetValueOrDefault(name);
        table[name] = (t.Points + points, t.For + goalsFor, t.Against + goalsAgainst);
    }

    // The lines of a CSV file this test's entrants never quote, read as UTF-8 with its byte-order mark.
    private static string[] ReadCsv(string path)
    {
        byte[] bytes = File.ReadAllBytes(path);
        Assert.Equal(new byte[] { 0xEF, 0xBB, 0xBF }, bytes[..3]);
        return Encoding.UTF8.GetString(bytes, 3, bytes.Length - 3).Split("\r\n", StringSplitOptions.RemoveEmptyEntries);
    }
}
