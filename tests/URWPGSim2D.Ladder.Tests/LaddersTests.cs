using System.Data.Common;
using Microsoft.Data.Sqlite;
using Npgsql;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// Several ladders in one service: the schema of a service of one ladder upgrades in place (SQLite
/// and PostgreSQL) and its rows keep playing; the organiser creates, lists, pauses and chooses
/// ladders through the API and the command line; a request that does not say which ladder when there
/// are several is refused with the choices; submissions, house entrants and standings are per
/// ladder; the workers take the ladders in turn.
/// </summary>
[Collection(PostgresCollection.Name)]
public sealed class LaddersTests(PostgresServer postgres) : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladders-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private static string Error(JsonElement body) => body.GetProperty("error").GetString()!;

    // The rows of a service of schema version 2 (one ladder per service), written as it wrote them:
    // ladder 1 (polo-1v1) with a house entrant, a team with two submissions (the second played a match),
    // then, a month later, ladder 2 (ball-grab) with a team whose submission never played.
    private static void WriteVersion2(DbConnection c, SqlDialect dialect)
    {
        void Run(string sql)
        {
            using var command = c.CreateCommand();
            command.CommandText = sql;
            command.ExecuteNonQuery();
        }

        Run("CREATE TABLE schema_version (version INTEGER NOT NULL)");
        for (int v = 0; v < 2; v++)
        {
            foreach (string statement in dialect.Migrations[v])
            {
                Run(statement);
            }

            Run($"INSERT INTO schema_version (version) VALUES ({v + 1})");
        }

        const string t = "'2026-01-01T00:00:00.0000000Z'";
        Run($"INSERT INTO ladders (item, cycles, first_seed, paused, created) VALUES ('polo-1v1', 600, 1, 0, {t})");
        Run($"INSERT INTO teams (name, token_hash, password_hash, house, created) VALUES ('house', 'h1', NULL, 'demo', {t})");
        Run($"INSERT INTO teams (name, token_hash, password_hash, house, created) VALUES ('coder', 'h2', NULL, NULL, {t})");
        Run($"INSERT INTO submissions (team_id, created, kind, path, state, log) VALUES (2, {t}, 'upload', 'a.cs', 'ok', 'ok')");
        Run($"INSERT INTO submissions (team_id, created, kind, path, state, log) VALUES (2, {t}, 'upload', 'b.cs', 'ok', 'ok')");
        Run($"INSERT INTO matches (ladder_id, seed, team_a, team_b, sub_a, sub_b, state, created, final) VALUES (1, 2, 1, 2, 0, 2, 'queued', {t}, 0)");
        const string later = "'2026-02-01T00:00:00.0000000Z'";
        Run($"INSERT INTO ladders (item, cycles, first_seed, paused, created) VALUES ('ball-grab', 600, 1, 0, {later})");
        Run($"INSERT INTO teams (name, token_hash, password_hash, house, created) VALUES ('grabber', 'h3', NULL, NULL, {later})");
        Run($"INSERT INTO submissions (team_id, created, kind, path, state, log) VALUES (3, {later}, 'upload', 'c.cs', 'ok', 'ok')");
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void AStoreOfOneLadderPerServiceUpgradesInPlace(string database)
    {
        SqlLadderStore store;
        if (database == "sqlite")
        {
            string path = Path.Combine(_folder, "ladder.db");
            using (var c = new SqliteConnection(new SqliteConnectionStringBuilder { DataSource = path, Pooling = false }.ToString()))
            {
                c.Open();
                WriteVersion2(c, SqlDialect.Sqlite);
            }

            store = SqlDialect.SqliteStore(path);
        }
        else
        {
            string connection = postgres.NewDatabase();
            using (var c = new NpgsqlConnection(connection))
            {
                c.Open();
                WriteVersion2(c, SqlDialect.PostgreSql);
            }

            store = SqlDialect.PostgreSqlStore(connection);
        }

        using (store)
        {
            Assert.Equal(2, store.SchemaVersion());
            store.Migrate();
            Assert.Equal(store.Dialect.Migrations.Count, store.SchemaVersion());

            // A submission that played is of its match's ladder; one that never did, of the newest ladder made
            // before it (the one the service ran then); the house entrant plays where it played.
            Assert.Equal([(3L, 2L), (2, 1), (1, 1)], store.Submissions(null).Select(s => (s.Id, s.LadderId)));
            Assert.Equal([("house", 1L), ("coder", 0), ("grabber", 0)], store.Teams().Select(t => (t.Name, t.LadderId)));
            Assert.Equal(2, store.NewestWorking(2, 1)!.Id);
            Assert.Null(store.NewestWorking(3, 1));
            Assert.Equal(3, store.NewestWorking(3, 2)!.Id);
        }
    }

    [Fact]
    public void ADataFolderOfOneLadderUpgradesOnStartAndKeepsPlaying()
    {
        string path = Path.Combine(_folder, "ladder.db");
        using (var c = new SqliteConnection(new SqliteConnectionStringBuilder { DataSource = path, Pooling = false }.ToString()))
        {
            c.Open();
            WriteVersion2(c, SqlDialect.Sqlite);
        }

        // Started as the older service was, with its item named: the ladder reopens, and both ladders run.
        using var service = new LadderService(SqlDialect.SqliteStore(path), new LadderSettings { Item = "polo-1v1", DataDir = _folder, AdminToken = "organiser-upgrade", Workers = 0 });
        Assert.Equal(1, service.Served);
        Assert.Equal([(1L, "polo-1v1"), (2, "ball-grab")], service.Cores().Select(c => (c.LadderId, c.Item.Slug)));
        Assert.Equal([(1L, 0L), (2, 2)], service.Core(1).Playing().Select(p => (p.Key, p.Value.Submission)).Order());
        Assert.Equal([(3L, 3L)], service.Core(2).Playing().Select(p => (p.Key, p.Value.Submission)));
        Assert.Equal(MatchRow.Queued, service.Store.Match(1)!.State);
    }

    private LadderService Service(int cycles = 600) => new(SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db")),
        new LadderSettings { Item = "polo-1v1", Cycles = cycles, DataDir = _folder, AdminToken = "organiser-ladders", Workers = 0 });

    [Fact]
    public void WorkersTakeTheLaddersInTurn()
    {
        using var service = Service(cycles: 60);
        var polo = service.Core(service.Served);
        var grab = service.CreateLadder("ball-grab", 60, 100);
        service.AddTeam("polo-a", "demo", "1");
        service.AddTeam("polo-b", "idle", "1");
        service.AddTeam("grab-a", "demo", "ball-grab");
        service.AddTeam("grab-b", "idle", "ball-grab");

        for (int k = 0; k < 4; k++)
        {
            Assert.True(service.PlayNext());
        }

        Assert.Equal((2, 2), (polo.Store.Records(polo.LadderId).Count, grab.Store.Records(grab.LadderId).Count));
        Assert.Equal(["polo-a", "polo-b"], polo.Standings().Standings.Rows.Select(r => r.Name).Order(StringComparer.Ordinal));
        Assert.Equal(["grab-a", "grab-b"], grab.Standings().Standings.Rows.Select(r => r.Name).Order(StringComparer.Ordinal));
        Assert.All(grab.Store.Matches(grab.LadderId, [], 100), m => Assert.Equal(100 + (ulong)m.Id, m.Seed));

        // A paused ladder (once the match it had queued is played) leaves the workers to the others.
        grab.SetPaused(true);
        while (grab.Store.ClaimNext(grab.LadderId) is { } waiting)
        {
            Assert.True(grab.Play(waiting));
        }

        int before = grab.Store.Records(grab.LadderId).Count;
        for (int k = 0; k < 3; k++)
        {
            Assert.True(service.PlayNext());
        }

        Assert.Equal(before, grab.Store.Records(grab.LadderId).Count);
        Assert.Equal(5, polo.Store.Records(polo.LadderId).Count);
    }

    [Fact]
    public async Task TheOrganiserRunsTwoLaddersThroughTheApi()
    {
        await using var host = await LadderHost.StartAsync(workers: 0);
        const string admin = LadderHost.AdminToken;

        // One ladder: nothing names it, as before.
        var one = await host.Get("/api/standings");
        Assert.True(one.Status == 200, one.Body.ToString());
        Assert.Equal(401, (await host.Send(HttpMethod.Post, "/api/ladders", null, "{\"item\": \"ball-grab\"}")).Status);
        foreach (var (json, message) in new[]
        {
            ("{\"item\": \"chess\"}", "item: unknown item \"chess\""),
            ("{\"item\": \"ball-grab\", \"minutes\": 2}", "minutes must be 10, 5, 3 or 1, got 2"),
            ("{\"item\": \"ball-grab\", \"minutes\": 1, \"cycles\": 600}", "minutes and cycles: give one of them, not both"),
            ("{\"item\": \"ball-grab\", \"cycles\": 0}", "cycles must be 1 to 36000, got 0"),
            ("{\"item\": \"ball-grab\", \"firstSeed\": -1}", "firstSeed must be a whole number from 0 to 18446744073709551615, got -1"),
        })
        {
            var bad = await host.Send(HttpMethod.Post, "/api/ladders", admin, json);
            Assert.Equal((400, message), (bad.Status, Error(bad.Body)));
        }

        var created = await host.Send(HttpMethod.Post, "/api/ladders", admin, "{\"item\": \"ball-grab\", \"minutes\": 1, \"firstSeed\": 50}");
        Assert.Equal(201, created.Status);
        Assert.Equal((2, "ball-grab", 600, "50", false), (created.Body.GetProperty("id").GetInt32(), created.Body.GetProperty("item").GetString(),
            created.Body.GetProperty("cycles").GetInt32(), created.Body.GetProperty("firstSeed").GetString(), created.Body.GetProperty("paused").GetBoolean()));

        var ladders = (await host.Get("/api/ladders")).Body;
        Assert.Equal(["polo-1v1", "ball-grab"], ladders.GetProperty("ladders").EnumerateArray().Select(l => l.GetProperty("item").GetString()));
        Assert.Contains("ball-grab", ladders.GetProperty("items").EnumerateArray().Select(i => i.GetString()));

        // Two ladders: a request that does not name one is refused with the choices.
        const string choose = "ladder: this service runs 2 ladders; name one: 1 (polo-1v1), 2 (ball-grab)";
        foreach (string path in new[] { "/api/standings", "/api/matches", "/api/ladder", "/api/teams", "/api/export/standings.json" })
        {
            var refused = await host.Get(path);
            Assert.Equal((400, choose), (refused.Status, Error(refused.Body)));
        }

        Assert.Equal((400, choose), await Refusal(host.Send(HttpMethod.Post, "/api/teams", admin, "{\"name\": \"h\", \"strategy\": \"demo\"}")));
        Assert.Equal((400, "ladder: no ladder \"3\"; this service runs 1 (polo-1v1), 2 (ball-grab)"), await Refusal(host.Get("/api/standings?ladder=3")));
        Assert.Equal((400, "ladder: only a house entrant is added to one ladder; a team that submits plays in every ladder it submits to"),
            await Refusal(host.Send(HttpMethod.Post, "/api/teams?ladder=2", admin, "{\"name\": \"x\"}")));

        // House entrants of each ladder; a team that submits to the second one only.
        Assert.Equal(201, (await host.Send(HttpMethod.Post, "/api/teams?ladder=1", admin, "{\"name\": \"polo house\", \"strategy\": \"demo\"}")).Status);
        var grabHouse = await host.Send(HttpMethod.Post, "/api/teams?ladder=ball-grab", admin, "{\"name\": \"grab house\", \"strategy\": \"idle\"}");
        Assert.Equal((201, 2), (grabHouse.Status, grabHouse.Body.GetProperty("ladder").GetInt32()));
        string token = (await host.Send(HttpMethod.Post, "/api/teams", admin, "{\"name\": \"coder\"}")).Body.GetProperty("token").GetString()!;
        string source = URWPGSim2D.Testing.SdkStrategy.Source("Still", "still", "d.Fill(Decision.Stop);");
        Assert.Equal((400, choose), await Refusal(host.Send(HttpMethod.Post, "/api/submissions", token, content: Upload(source))));
        var submitted = await host.Send(HttpMethod.Post, "/api/submissions?ladder=2", token, content: Upload(source));
        Assert.Equal((201, 2), (submitted.Status, submitted.Body.GetProperty("ladder").GetInt32()));

        Assert.Equal(["polo house"], Names(await host.Get("/api/teams?ladder=1"), "teams").Where(n => n != "coder"));
        Assert.Equal(["coder", "grab house"], Names(await host.Get("/api/teams?ladder=2"), "teams").Order(StringComparer.Ordinal));
        Assert.Equal(["polo house"], Names(await host.Get("/api/standings?ladder=1"), "entrants"));
        var grabStandings = (await host.Get("/api/standings?ladder=ball-grab")).Body;
        Assert.Equal("ball-grab", grabStandings.GetProperty("item").GetString());
        Assert.Equal(["coder", "grab house"], Names((200, grabStandings), "entrants").Order(StringComparer.Ordinal));

        // Each ladder pauses alone.
        Assert.Equal(200, (await host.Send(HttpMethod.Post, "/api/ladder/pause?ladder=2", admin)).Status);
        Assert.True((await host.Get("/api/ladder?ladder=2")).Body.GetProperty("paused").GetBoolean());
        Assert.False((await host.Get("/api/ladder?ladder=1")).Body.GetProperty("paused").GetBoolean());
    }

    private static async Task<(int, string)> Refusal(Task<(int Status, JsonElement Body)> answer)
    {
        var (status, body) = await answer;
        return (status, Error(body));
    }

    private static MultipartFormDataContent Upload(string source) =>
        new() { { new ByteArrayContent(Encoding.UTF8.GetBytes(source)), "file", "Still.cs" } };

    private static List<string> Names((int Status, JsonElement Body) answer, string list) =>
        [.. answer.Body.GetProperty(list).EnumerateArray().Select(e => e.GetProperty("name").GetString()!)];

    [Fact]
    public async Task TheCommandLineNamesTheLadderWhenThereAreSeveral()
    {
        const string admin = "organiser-ladders-cli";
        string data = Path.Combine(_folder, "cli");
        using var serve = await ServeProcess.StartAsync("ladder", "serve", "--item", "polo-1v1", "--data", data, "--port", "0", "--workers", "0", "--admin-token", admin);
        Assert.Matches(@"^ladder: polo-1v1 at http://127\.0\.0\.1:\d+/ ", serve.FirstLine);

        // One ladder: the commands as before.
        Assert.Equal(0, (await ServeProcess.RunAsync("ladder", "team", "add", "polo house", "--server", serve.Url, "--admin-token", admin, "--strategy", "demo")).Code);

        var created = await ServeProcess.RunAsync("ladder", "create", "--server", serve.Url, "--admin-token", admin, "--item", "ball-grab", "--minutes", "1", "--first-seed", "9");
        Assert.Equal((0, "ladder 2 created: ball-grab, 600 cycles a match, first seed 9\n", string.Empty), created);
        var bad = await ServeProcess.RunAsync("ladder", "create", "--server", serve.Url, "--admin-token", admin, "--item", "ball-grab", "--first-seed", "x");
        Assert.Equal((2, string.Empty, "ladder create: --first-seed must be a whole number from 0 to 18446744073709551615, got \"x\"\n"), bad);

        var ambiguous = await ServeProcess.RunAsync("ladder", "team", "add", "grab house", "--server", serve.Url, "--admin-token", admin, "--strategy", "idle");
        Assert.Equal((2, string.Empty, "ladder team add: --ladder: this service runs 2 ladders; name one: 1 (polo-1v1), 2 (ball-grab)\n"), ambiguous);
        Assert.Equal(0, (await ServeProcess.RunAsync("ladder", "team", "add", "grab house", "--server", serve.Url, "--admin-token", admin, "--strategy", "idle", "--ladder", "ball-grab")).Code);
        var unknown = await ServeProcess.RunAsync("ladder", "pause", "--server", serve.Url, "--admin-token", admin, "--ladder", "7");
        Assert.Equal((2, string.Empty, "ladder pause: --ladder: no ladder \"7\"; this service runs 1 (polo-1v1), 2 (ball-grab)\n"), unknown);

        var paused = await ServeProcess.RunAsync("ladder", "pause", "--server", serve.Url, "--admin-token", admin, "--ladder", "2");
        Assert.Equal((0, "ladder 2: ball-grab, 600 cycles a match, paused\n", string.Empty), paused);
        var list = await ServeProcess.RunAsync("ladder", "list", "--server", serve.Url);
        Assert.Equal((0, "ladder 1: polo-1v1, 6000 cycles a match, playing; 1 team, 0 matches\nladder 2: ball-grab, 600 cycles a match, paused; 1 team, 0 matches\n", string.Empty), list);
        var resumed = await ServeProcess.RunAsync("ladder", "resume", "--server", serve.Url, "--admin-token", admin, "--ladder", "ball-grab");
        Assert.Equal((0, "ladder 2: ball-grab, 600 cycles a match, playing\n", string.Empty), resumed);

        // A restart names both ladders on its first line, and --item still reopens the one of that item.
        serve.KillHard();
        using var again = await ServeProcess.StartAsync("ladder", "serve", "--item", "ball-grab", "--data", data, "--port", "0", "--workers", "0", "--admin-token", admin);
        Assert.Matches(@"^ladders: 1 polo-1v1, 2 ball-grab at http://127\.0\.0\.1:\d+/ \(data: .*, SQLite\); Ctrl\+C stops it$", again.FirstLine);
        var final = await ServeProcess.RunAsync("ladder", "final", "--server", again.Url, "--admin-token", admin, "--top", "2");
        Assert.Equal((2, string.Empty, "ladder final: --ladder: this service runs 2 ladders; name one: 1 (polo-1v1), 2 (ball-grab)\n"), final);
    }
}
