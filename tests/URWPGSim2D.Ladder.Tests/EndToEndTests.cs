namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// A whole ladder in this process: the organiser adds two house entrants and a team, the team
/// submits its sources (a folder, sent as a .zip by the client), ranked matches play in sandboxed
/// strategy hosts, and the standings order the known strengths: in one-minute water polo 1v1 the
/// item's demo beats a fish that does not move (it scores; the others cannot).
/// </summary>
public sealed class EndToEndTests : IAsyncLifetime
{
    private LadderHost _host = null!;
    private readonly string _sources = Directory.CreateTempSubdirectory("urwpg-ladder-src-").FullName;

    public async Task InitializeAsync() => _host = await LadderHost.StartAsync(workers: 1);

    public async Task DisposeAsync()
    {
        await _host.DisposeAsync();
        Directory.Delete(_sources, recursive: true);
    }

    // A team whose fish do not move.
    private static readonly string Still = URWPGSim2D.Testing.SdkStrategy.Source("Still", "still", "d.Fill(Decision.Stop);");

    [Fact]
    public async Task TeamsSubmitMatchesPlayAndTheStandingsOrderKnownStrengths()
    {
        using var organiser = new LadderClient(_host.Server.Url, LadderHost.AdminToken);
        await organiser.AddTeamAsync("champion", "demo");
        await organiser.AddTeamAsync("sleeper", "idle");
        var (_, token) = await organiser.AddTeamAsync("coder", null);

        Directory.CreateDirectory(Path.Combine(_sources, "inner"));
        File.WriteAllText(Path.Combine(_sources, "inner", "Still.cs"), Still);
        using var team = new LadderClient(_host.Server.Url, token);
        var (id, ok, log) = await team.SubmitAsync(_sources);
        Assert.True(ok, log);

        JsonElement standings = default;
        await LadderHost.Until(async () =>
        {
            standings = (await _host.Get("/api/standings")).Body;
            var entrants = standings.GetProperty("entrants").EnumerateArray().ToList();
            return entrants.Count == 3 && entrants.All(e => e.GetProperty("played").GetInt32() >= 4);
        }, "every team has played four matches");

        var rows = standings.GetProperty("entrants").EnumerateArray().ToList();
        Assert.Equal("polo-1v1", standings.GetProperty("item").GetString());
        Assert.Equal("champion", rows[0].GetProperty("name").GetString());
        Assert.True(rows[0].GetProperty("rating").GetDouble() > rows[1].GetProperty("rating").GetDouble());
        Assert.Equal(0, rows[0].GetProperty("losses").GetInt32());

        // The queue and the matches name the submission each team played with; every finished match has its replay page.
        var matches = (await _host.Get("/api/matches?team=coder&state=done")).Body.GetProperty("matches").EnumerateArray().ToList();
        Assert.NotEmpty(matches);
        foreach (var m in matches)
        {
            int side = m.GetProperty("teams").EnumerateArray().Select(t => t.GetString()).ToList().IndexOf("coder");
            Assert.Equal(id, m.GetProperty("submissions")[side].GetInt64());
            string replay = await _host.Http.GetStringAsync(m.GetProperty("replay").GetString());
            Assert.Contains("<html", replay, StringComparison.OrdinalIgnoreCase);
        }

        // The export is a tournament result file: its header and one record per finished match, each once.
        string results = await _host.Http.GetStringAsync("/api/export/results.jsonl");
        string file = Path.Combine(_sources, "results.jsonl");
        File.WriteAllText(file, results);
        var (header, records, broken) = URWPGSim2D.Tournament.TournamentFile.Read(file);
        Assert.Equal((0, "polo-1v1"), (broken, header.Item));
        Assert.Equal(records.Count, records.Select(r => r.Index).Distinct().Count());
        Assert.True(records.Count >= standings.GetProperty("matches").GetInt32());
    }
}
