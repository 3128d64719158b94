namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// A team's page shows its strategy's faults (summed as the tournament sums them) and the slowest
/// call of each match, and its own strategy's log per match: what it printed, to the team alone
/// (another team is refused, no token is refused, and the public replay page does not carry it).
/// </summary>
public sealed class TeamOutputsTests : IAsyncLifetime
{
    private LadderHost _host = null!;

    public async Task InitializeAsync() => _host = await LadderHost.StartAsync(workers: 1);

    public async Task DisposeAsync() => await _host.DisposeAsync();

    // Prints on every hundredth call and throws once, on the call of snapshot cycle 250: one exception a match.
    private const string Talker = """
        using System;
        using URWPGSim2D.Strategies;

        public sealed class Talker : IStrategy
        {
            public string TeamName => "talker";

            public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
            {
                if (snapshot.Cycle % 100 == 0)
                {
                    Console.WriteLine($"secret-plan {snapshot.Cycle}");
                }

                if (snapshot.Cycle == 250)
                {
                    throw new InvalidOperationException("talker slipped");
                }

                for (int k = 0; k < decisions.Length; k++)
                {
                    decisions[k] = Decision.Stop;
                }
            }
        }
        """;

    [Fact]
    public async Task ATeamSeesItsFaultsAndOnlyItsOwnLogs()
    {
        var organiser = await _host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, "{\"name\": \"talker\"}");
        string token = organiser.Body.GetProperty("token").GetString()!;
        string other = (await _host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, "{\"name\": \"rival\"}")).Body.GetProperty("token").GetString()!;
        await _host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, "{\"name\": \"house\", \"strategy\": \"idle\"}");
        using var form = new MultipartFormDataContent { { new ByteArrayContent(Encoding.UTF8.GetBytes(Talker)), "file", "Talker.cs" } };
        var submitted = await _host.Send(HttpMethod.Post, "/api/submissions", token, content: form);
        Assert.Equal(201, submitted.Status);

        await LadderHost.Until(async () => (await _host.Get("/api/matches?team=talker&state=done")).Body.GetProperty("matches").GetArrayLength() >= 2, "talker played two matches");
        await _host.Send(HttpMethod.Post, "/api/ladder/pause", LadderHost.AdminToken);
        await LadderHost.Until(async () => (await _host.Get("/api/matches?state=running")).Body.GetProperty("matches").GetArrayLength() == 0, "the running match finished");

        // Faults: its matches' faults summed (one exception a match that reached that call; on a loaded machine a
        // call may also miss its deadline), the first one named; each match's slowest call.
        var done = (await _host.Get("/api/matches?team=talker&state=done")).Body.GetProperty("matches").EnumerateArray().OrderBy(m => m.GetProperty("id").GetInt64()).ToList();
        var team = (await _host.Get("/api/teams/talker")).Body;
        var faults = team.GetProperty("faults");
        var mine = done.Select(m => m.GetProperty("sideFaults")[m.GetProperty("teams").EnumerateArray().Select(t => t.GetString()).ToList().IndexOf("talker")]).ToList();
        int Sum(string kind) => mine.Where(f => f.ValueKind == System.Text.Json.JsonValueKind.Object).Sum(f => f.GetProperty(kind).GetInt32());
        string detail = string.Join(" | ", mine.Select(f => f.GetRawText()));
        Assert.True(mine.Count(f => f.ValueKind == System.Text.Json.JsonValueKind.Object && f.GetProperty("exceptions").GetInt32() == 1 && f.GetProperty("first").GetString()!.Contains("talker slipped", StringComparison.Ordinal)) >= 1, detail);
        Assert.All(mine, f => Assert.True(f.ValueKind == System.Text.Json.JsonValueKind.Null || f.GetProperty("exceptions").GetInt32() <= 1, detail));
        Assert.Equal(
            (Sum("exceptions"), Sum("timeouts"), Sum("badAnswers"), Sum("hostEnds"), mine.Count(f => f.ValueKind == System.Text.Json.JsonValueKind.Object)),
            (faults.GetProperty("exceptions").GetInt32(), faults.GetProperty("timeouts").GetInt32(), faults.GetProperty("badAnswers").GetInt32(), faults.GetProperty("hostEnds").GetInt32(), faults.GetProperty("matches").GetInt32()));
        int first = mine.FindIndex(f => f.ValueKind == System.Text.Json.JsonValueKind.Object);
        Assert.Equal(done[first].GetProperty("id").GetInt64(), faults.GetProperty("first").GetProperty("match").GetInt64());
        foreach (var m in done)
        {
            int side = m.GetProperty("teams").EnumerateArray().Select(t => t.GetString()).ToList().IndexOf("talker");
            Assert.True(m.GetProperty("slowestMs")[side].GetDouble() >= 0); // a submission plays in a strategy host: its calls are timed
        }

        // Its log: what it printed, each cycle's output once, to itself only.
        int clean = mine.FindIndex(f => f.ValueKind == System.Text.Json.JsonValueKind.Object && f.GetProperty("exceptions").GetInt32() == 1
            && f.GetProperty("timeouts").GetInt32() == 0 && f.GetProperty("hostEnds").GetInt32() == 0 && f.GetProperty("badAnswers").GetInt32() == 0);
        Assert.True(clean >= 0, "a match where the strategy was called every cycle: " + detail);
        long id = done[clean].GetProperty("id").GetInt64();
        string path = $"/api/teams/talker/matches/{id}/log";
        var own = await _host.Get(path, token);
        Assert.Equal(200, own.Status);
        string log = own.Body.GetProperty("log").GetString()!;
        for (int cycle = 0; cycle < 600; cycle += 100)
        {
            Assert.Equal(1, log.Split('\n').Count(l => l.EndsWith($": secret-plan {cycle}", StringComparison.Ordinal)));
        }

        Assert.All(log.TrimEnd('\n').Split('\n'), l => Assert.StartsWith("cycle ", l, StringComparison.Ordinal));
        Assert.Equal((403, "authorization: a team's strategy log is its own"), ((await _host.Get(path, other)).Status, (await _host.Get(path, other)).Body.GetProperty("error").GetString()));
        Assert.Equal(401, (await _host.Get(path)).Status);
        Assert.Equal(404, (await _host.Get($"/api/teams/rival/matches/{id}/log", other)).Status); // rival did not play it

        // The replay page is public and carries no printed text.
        string replay = await _host.Http.GetStringAsync(done[0].GetProperty("replay").GetString());
        Assert.DoesNotContain("secret-plan", replay, StringComparison.Ordinal);
        Assert.DoesNotContain("secret-plan", (await _host.Http.GetStringAsync("/api/matches?team=talker")), StringComparison.Ordinal);
    }
}
