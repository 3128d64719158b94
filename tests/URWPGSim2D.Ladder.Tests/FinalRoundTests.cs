namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// The final round: every pair of the top K plays the same number of matches, each side as often,
/// ranked play stops and the standings are the final's alone (marked final) and stay so however long
/// the workers would otherwise play. Matches are played one by one in this thread (no worker).
/// </summary>
public sealed class FinalRoundTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-final-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private LadderService Service() => new(SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db")),
        new LadderSettings { Item = "polo-1v1", Cycles = 600, DataDir = _folder, AdminToken = "organiser-final", Workers = 0 });

    private static List<string> Names(JsonElement standings) =>
        [.. standings.GetProperty("entrants").EnumerateArray().Select(e => e.GetProperty("name").GetString()!)];

    [Fact]
    public void EveryPairOfTheTopPlaysAsOftenAndTheStandingsFreeze()
    {
        using var service = Service();
        var core = service.Core(service.Served);
        foreach (var (name, house) in new[] { ("champion", "demo"), ("chaser", "chase-ball"), ("sleeper", "idle"), ("dozer", "idle"), ("napper", "idle") })
        {
            service.AddTeam(name, house, null);
        }

        for (int k = 0; k < 10; k++)
        {
            Assert.True(core.PlayNext()); // ranked play never runs out of matches
        }

        int ranked = core.Store.Records(core.LadderId).Count;
        Assert.NotEmpty(core.Store.Matches(core.LadderId, [MatchRow.Queued], 100)); // a ranked match waits: the final drops it
        using var before = JsonDocument.Parse(core.Standings().Json);
        Assert.False(before.RootElement.TryGetProperty("final", out _));
        var top = Names(before.RootElement).Take(3).ToList();

        var final = core.StartFinal(3, 2);
        Assert.Equal((3, 2, 0, 6), (final.Teams.Count, final.Rounds, final.Played, final.Matches));
        var queued = core.Store.Matches(core.LadderId, [MatchRow.Queued], 100);
        Assert.Equal((6, 6), (queued.Count, queued.Count(m => m.Final))); // the ranked match that waited is dropped
        Assert.Equal("final: the final round has started already", Assert.Throws<LadderInputException>(() => core.StartFinal(3, 2)).Message);

        int played = 0;
        while (core.PlayNext())
        {
            played++;
            Assert.True(played <= 6, "ranked play goes on after the final round started");
        }

        // Only the final's six matches played, and ranked play stays stopped: a new team changes nothing.
        Assert.Equal(6, played);
        service.AddTeam("latecomer", "demo", null);
        Assert.False(core.PlayNext());
        Assert.Null(core.MakeMatch(10));

        // Each pair of the top three played twice, once on each side (sides as played: odd ids swap).
        var teams = core.Store.Teams().ToDictionary(t => t.Id, t => t.Name);
        var finals = core.Store.FinalMatches(core.LadderId);
        Assert.All(finals, m => Assert.Equal(MatchRow.Done, m.State));
        var sides = finals.Select(m => m.Id % 2 == 0 ? (teams[m.Teams[0]], teams[m.Teams[1]]) : (teams[m.Teams[1]], teams[m.Teams[0]])).ToList();
        for (int i = 0; i < 3; i++)
        {
            for (int j = i + 1; j < 3; j++)
            {
                Assert.Equal(1, sides.Count(s => s == (top[i], top[j])));
                Assert.Equal(1, sides.Count(s => s == (top[j], top[i])));
            }
        }

        // The standings: the final's matches alone, its three teams with four games each, marked final.
        using var after = JsonDocument.Parse(core.Standings().Json);
        var root = after.RootElement;
        Assert.True(root.GetProperty("final").GetBoolean());
        var progress = root.GetProperty("finalRound");
        Assert.Equal((3, 2, 6, 6), (progress.GetProperty("top").GetInt32(), progress.GetProperty("rounds").GetInt32(), progress.GetProperty("played").GetInt32(), progress.GetProperty("matches").GetInt32()));
        Assert.Equal(6, root.GetProperty("matches").GetInt32());
        Assert.Equal(top.Order(StringComparer.Ordinal), Names(root).Order(StringComparer.Ordinal));
        Assert.All(root.GetProperty("entrants").EnumerateArray(), e => Assert.Equal(4, e.GetProperty("played").GetInt32()));
        Assert.Equal(ranked + 6, core.Store.Records(core.LadderId).Count); // the ranked records are kept, apart
    }

    [Fact]
    public async Task TheOrganiserStartsTheFinalThroughTheApi()
    {
        await using var host = await LadderHost.StartAsync(workers: 0);
        string team = (await host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, "{\"name\": \"a\", \"strategy\": \"demo\"}")).Body.GetProperty("token").GetString()!;
        await host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, "{\"name\": \"b\", \"strategy\": \"idle\"}");

        Assert.Equal(401, (await host.Send(HttpMethod.Post, "/api/final", team, "{\"top\": 2}")).Status);
        var tooMany = await host.Send(HttpMethod.Post, "/api/final", LadderHost.AdminToken, "{\"top\": 3}");
        Assert.Equal((400, "top: 2 teams can play, fewer than 3"), (tooMany.Status, tooMany.Body.GetProperty("error").GetString()));
        var badRounds = await host.Send(HttpMethod.Post, "/api/final", LadderHost.AdminToken, "{\"top\": 2, \"rounds\": \"two\"}");
        Assert.Equal((400, "rounds must be a whole number, got \"two\""), (badRounds.Status, badRounds.Body.GetProperty("error").GetString()));

        var started = await host.Send(HttpMethod.Post, "/api/final", LadderHost.AdminToken, "{\"top\": 2, \"rounds\": 3}");
        Assert.Equal(201, started.Status);
        var final = started.Body.GetProperty("final");
        Assert.Equal((3, 0), (final.GetProperty("matches").GetInt32(), final.GetProperty("played").GetInt32()));
        Assert.Equal(["a", "b"], final.GetProperty("teams").EnumerateArray().Select(t => t.GetString()).Order(StringComparer.Ordinal));

        var standings = (await host.Get("/api/standings")).Body;
        Assert.True(standings.GetProperty("final").GetBoolean());
        using var export = JsonDocument.Parse(await host.Http.GetStringAsync("/api/export/standings.json"));
        Assert.True(export.RootElement.GetProperty("final").GetBoolean());
        Assert.Equal(3, (await host.Get("/api/ladder")).Body.GetProperty("final").GetProperty("matches").GetInt32());
        Assert.Equal(3, (await host.Get("/api/matches?state=queued")).Body.GetProperty("matches").EnumerateArray().Count(m => m.GetProperty("final").GetBoolean()));
    }
}
