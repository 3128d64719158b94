using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder.Tests;

/// <summary><c>ladder serve --database</c> against a real PostgreSQL server: the ladder's rows are there, matches play and their records are written once.</summary>
[Collection(PostgresCollection.Name)]
public sealed class PostgresServeTests(PostgresServer postgres) : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-pg-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public async Task ServeKeepsTheLadderInPostgreSql()
    {
        string database = postgres.NewDatabase();
        const string admin = "organiser-postgres";
        using (var serve = await ServeProcess.StartAsync("ladder", "serve", "--item", "polo-1v1", "--minutes", "1", "--data", _folder, "--database", database, "--port", "0", "--admin-token", admin))
        {
            Assert.Contains("PostgreSQL", serve.FirstLine, StringComparison.Ordinal);
            using var organiser = new LadderClient(serve.Url, admin);
            await organiser.AddTeamAsync("strong", "demo");
            await organiser.AddTeamAsync("weak", "idle");
            using var watch = SqlDialect.PostgreSqlStore(database);
            await LadderHost.Until(() => Task.FromResult(watch.Records(1).Count >= 2), "two matches played");
        }

        // The rows are in PostgreSQL (no SQLite file was made), each record once, for its own match and seed.
        Assert.False(File.Exists(Path.Combine(_folder, "ladder.db")));
        using var store = SqlDialect.PostgreSqlStore(database);
        Assert.Equal(["strong", "weak"], store.Teams().Select(t => t.Name));
        var records = store.Records(1);
        Assert.True(records.Count >= 2);
        foreach (var (id, line, _) in records)
        {
            var r = TournamentFile.ParseRecord(line);
            Assert.Equal((id, store.Match(id)!.Seed), (r.Index, r.Seed));
            Assert.NotNull(r.Result);
        }
    }

    [Fact]
    public async Task TwoLaddersBothPlayThroughTheJobs()
    {
        string database = postgres.NewDatabase();
        const string admin = "organiser-postgres-two";
        using var serve = await ServeProcess.StartAsync("ladder", "serve", "--item", "polo-1v1", "--minutes", "1", "--data", _folder, "--database", database, "--port", "0", "--admin-token", admin);
        using (var organiser = new LadderClient(serve.Url, admin))
        {
            var created = await organiser.CreateLadderAsync("ball-grab", 600, 1);
            Assert.Equal((2L, "ball-grab", 600), (created.Id, created.Item, created.Cycles));
        }

        using (var polo = new LadderClient(serve.Url, admin, "1"))
        {
            await polo.AddTeamAsync("polo strong", "demo");
            await polo.AddTeamAsync("polo weak", "idle");
        }

        using (var grab = new LadderClient(serve.Url, admin, "ball-grab"))
        {
            await grab.AddTeamAsync("grab strong", "demo");
            await grab.AddTeamAsync("grab weak", "idle");
        }

        // One worker thread, two ladders: the jobs serve both, each match with its ladder's teams and item.
        using var watch = SqlDialect.PostgreSqlStore(database);
        await LadderHost.Until(() => Task.FromResult(watch.Records(1).Count >= 2 && watch.Records(2).Count >= 2), "two matches played in each ladder");
        var teams = watch.Teams().ToDictionary(t => t.Id, t => t.Name);
        foreach (var (ladder, prefix) in new[] { (1L, "polo "), (2L, "grab ") })
        {
            foreach (var (id, _, _) in watch.Records(ladder))
            {
                Assert.All(watch.Match(id)!.Teams, t => Assert.StartsWith(prefix, teams[t], StringComparison.Ordinal));
            }
        }
    }

    [Fact]
    public async Task AnUnreachableDatabaseIsOneLineAndExitTwo()
    {
        var (code, output, error) = await ServeProcess.RunAsync("ladder", "serve", "--data", _folder, "--database", $"Host={_folder}/none;Database=ladder;Timeout=5", "--port", "0");
        Assert.Equal(2, code);
        Assert.Equal(string.Empty, output);
        Assert.StartsWith("ladder serve: --database: cannot use the PostgreSQL database: ", error, StringComparison.Ordinal);
        Assert.Single(error.TrimEnd('\n').Split('\n'));
    }
}
