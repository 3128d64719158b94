using Microsoft.Data.Sqlite;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// Submissions' and matches' files kept in the database, the same tests on SQLite and on a real
/// PostgreSQL server: a match's files are written with its record, once, and dropped by a requeue; a
/// submission's files come back byte for byte; a second data folder (another machine's) plays a
/// submission and reads a match's outputs from the database alone.
/// </summary>
[Collection(PostgresCollection.Name)]
public sealed class FilesTests(PostgresServer postgres) : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-files-").FullName;
    private readonly List<SqlLadderStore> _stores = [];

    public void Dispose()
    {
        foreach (var s in _stores)
        {
            s.Dispose();
        }

        Directory.Delete(_folder, recursive: true);
    }

    private SqlLadderStore Store(string database)
    {
        var store = database == "sqlite" ? SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db")) : SqlDialect.PostgreSqlStore(postgres.NewDatabase());
        _stores.Add(store);
        store.Migrate();
        return store;
    }

    // Bytes that compress badly, so that their round trip through gzip is tested on more than zeros.
    private static byte[] Noise(int length, int seed)
    {
        var bytes = new byte[length];
        new Random(seed).NextBytes(bytes);
        return bytes;
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void AMatchsFilesAreWrittenWithItsRecordOnceAndARequeueDropsThem(string database)
    {
        var store = Store(database);
        var ladder = store.OpenLadder("polo-1v1", 600, 7);
        var a = store.AddTeam("a", "ha", "demo")!;
        var b = store.AddTeam("b", "hb", "idle")!;
        var m = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], false, id => (ulong)id);
        Assert.True(store.Claim(m.Id));

        byte[] replay = Noise(300_000, 1);
        Assert.True(store.FinishMatch(m.Id, "{}", [StoredFile.Of("outputs.json", "{\"sides\":[]}"u8.ToArray()), StoredFile.Of("replay.html", replay)]));
        Assert.False(store.FinishMatch(m.Id, "{}", [StoredFile.Of("replay.html", Noise(10, 2))])); // written once: the second play's files are not kept
        Assert.Equal([("outputs.json", StoredFile.Hash("{\"sides\":[]}"u8)), ("replay.html", StoredFile.Hash(replay))], store.MatchFileHashes(m.Id));
        Assert.Equal(replay, store.MatchFile(m.Id, "replay.html")!.Bytes);
        Assert.Empty(store.MatchesWithoutFiles());
        Assert.False(store.AddMatchFiles(m.Id, [StoredFile.Of("replay.html", Noise(10, 3))])); // it has its files

        Assert.True(store.Requeue(m.Id));
        Assert.Empty(store.MatchFileHashes(m.Id));
        Assert.Null(store.MatchFile(m.Id, "replay.html"));
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void ASubmissionPlaysFromAnotherDataFolderWithTheDatabaseAlone(string database)
    {
        var store = Store(database);
        var team = store.AddTeam("coder", "hc", null)!;
        var row = store.AddSubmission(team.Id, "upload", DateTime.UtcNow);

        // The service's folder: the upload kept, its folder becoming its copy.
        string service = Path.Combine(_folder, "service");
        string upload = Path.Combine(service, "submissions", row.Id.ToString(System.Globalization.CultureInfo.InvariantCulture));
        Directory.CreateDirectory(Path.Combine(upload, "src", "deep"));
        File.WriteAllText(Path.Combine(upload, "src", "A.cs"), "// a");
        File.WriteAllBytes(Path.Combine(upload, "src", "deep", "B.cs"), Noise(5000, 4));
        var files = new LadderFiles(store, service);
        string spec = files.Keep(row.Id, upload, Path.Combine(upload, "src"));
        Assert.False(Directory.Exists(upload));
        Assert.Equal("src", Path.GetFileName(spec));
        Assert.Equal(["src/A.cs", "src/deep/B.cs"], store.SubmissionFiles(row.Id).Select(f => f.Name));
        Assert.Empty(store.SubmissionsWithoutFiles());

        // Another machine's folder: the same files, from the database, once the service's folder is gone.
        Directory.Delete(service, recursive: true);
        string worker = Path.Combine(_folder, "worker");
        var other = new LadderFiles(store, worker);
        string copy = other.Spec(store.Submission(row.Id)!);
        Assert.StartsWith(Path.GetFullPath(worker) + Path.DirectorySeparatorChar, copy, StringComparison.Ordinal);
        Assert.Equal("// a", File.ReadAllText(Path.Combine(copy, "A.cs")));
        Assert.Equal(Noise(5000, 4), File.ReadAllBytes(Path.Combine(copy, "deep", "B.cs")));
        Assert.Equal(copy, new LadderFiles(store, worker).Spec(store.Submission(row.Id)!)); // a restarted worker finds its copy

        // A match it plays: the replay page goes to the database with the record; the service reads it from there.
        var ladder = store.OpenLadder("polo-1v1", 600, 7);
        var house = store.AddTeam("house", "hh", "idle")!;
        var m = store.AddMatch(ladder.Id, [team.Id, house.Id], [row.Id, 0], false, id => (ulong)id);
        store.Claim(m.Id);
        string played = other.PlayingReplay(m.Id);
        Directory.CreateDirectory(Path.GetDirectoryName(played)!);
        File.WriteAllText(played, "<html>replay</html>");
        Assert.True(other.Finish(m.Id, "{}", played, "{\"sides\":[]}"));
        Assert.False(File.Exists(played));
        var reader = new LadderFiles(store, Path.Combine(_folder, "service-again"));
        Assert.True(reader.Has(m.Id, LadderFiles.Replay));
        Assert.Equal("<html>replay</html>"u8.ToArray(), reader.Read(m.Id, LadderFiles.Replay));
        Assert.Equal("{\"sides\":[]}"u8.ToArray(), reader.Read(m.Id, LadderFiles.Outputs));

        // A second play of the same match writes nothing and leaves no file behind.
        string again = other.PlayingReplay(m.Id);
        File.WriteAllText(again, "<html>other</html>");
        Assert.False(other.Finish(m.Id, "{}", again, "{}"));
        Assert.False(File.Exists(again));
        Assert.Equal("<html>replay</html>"u8.ToArray(), reader.Read(m.Id, LadderFiles.Replay));
    }
}

/// <summary>
/// A data folder of the version before files moved into the database (schema version 2: submissions in
/// <c>submissions/ID/</c>, replay pages in <c>replays/match-ID.html</c>, outputs in
/// <c>outputs/match-ID.json</c>) is read into the database when the service starts on it: its replay
/// pages, logs and submissions are served and played as before, and a second data folder reads them
/// from the database alone.
/// </summary>
public sealed class UpgradeTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-upgrade-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private static readonly string Still = URWPGSim2D.Testing.SdkStrategy.Source("Still", "still", "d.Fill(Decision.Stop);");

    [Fact]
    public async Task AnOlderDataFolderIsReadIntoTheDatabaseOnStart()
    {
        string token;
        long played;
        string log;
        await using (var host = await LadderHost.StartAsync(workers: 1, folder: _folder))
        {
            token = (await host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, "{\"name\": \"coder\"}")).Body.GetProperty("token").GetString()!;
            await host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, "{\"name\": \"house\", \"strategy\": \"idle\"}");
            using var form = new MultipartFormDataContent { { new ByteArrayContent(Encoding.UTF8.GetBytes(Still)), "file", "Still.cs" } };
            Assert.Equal(201, (await host.Send(HttpMethod.Post, "/api/submissions", token, content: form)).Status);
            await LadderHost.Until(async () => (await host.Get("/api/matches?state=done")).Body.GetProperty("matches").GetArrayLength() >= 1, "a match played");
            await host.Send(HttpMethod.Post, "/api/ladder/pause", LadderHost.AdminToken);
            await LadderHost.Until(async () => (await host.Get("/api/matches?state=running")).Body.GetProperty("matches").GetArrayLength() == 0, "the running match finished");
            played = (await host.Get("/api/matches?state=done")).Body.GetProperty("matches")[0].GetProperty("id").GetInt64();
            log = (await host.Get($"/api/teams/coder/matches/{played}/log", token)).Body.GetProperty("log").GetString()!;
        }

        // The folder as the older version left it.
        var old = Downgrade();
        Assert.True(old.Replays.ContainsKey(played));

        await using (var host = await LadderHost.StartAsync(workers: 1, folder: _folder))
        {
            using var store = SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db"));
            Assert.Equal(store.Dialect.Migrations.Count, store.SchemaVersion());
            Assert.Empty(store.SubmissionsWithoutFiles());
            Assert.Empty(store.MatchesWithoutFiles());
            foreach (var (id, bytes) in old.Submissions)
            {
                Assert.Equal(bytes, store.SubmissionFiles(id).Single().Bytes);
                Assert.False(Directory.Exists(Path.Combine(_folder, "submissions", id.ToString(System.Globalization.CultureInfo.InvariantCulture)))); // moved to its copy
            }

            // Served as before.
            foreach (var (id, bytes) in old.Replays)
            {
                Assert.Equal(bytes, await host.Http.GetByteArrayAsync($"/matches/{id}/replay"));
            }

            Assert.Equal(log, (await host.Get($"/api/teams/coder/matches/{played}/log", token)).Body.GetProperty("log").GetString());
            var listed = (await host.Get("/api/matches?state=done")).Body.GetProperty("matches").EnumerateArray().Single(m => m.GetProperty("id").GetInt64() == played);
            Assert.Equal($"/matches/{played}/replay", listed.GetProperty("replay").GetString());

            // Another folder reads them from the database alone.
            var elsewhere = new LadderFiles(store, Path.Combine(_folder, "elsewhere"));
            foreach (var (id, bytes) in old.Replays)
            {
                Assert.Equal(bytes, elsewhere.Read(id, LadderFiles.Replay));
            }

            foreach (var (id, bytes) in old.Submissions)
            {
                Assert.Equal(bytes, File.ReadAllBytes(elsewhere.Spec(store.Submission(id)!)));
            }

            // And the submission plays on.
            int before = old.Replays.Count;
            await host.Send(HttpMethod.Post, "/api/ladder/resume", LadderHost.AdminToken);
            await LadderHost.Until(async () => (await host.Get("/api/matches?state=done")).Body.GetProperty("matches").GetArrayLength() > before, "a match played after the upgrade");
            var next = (await host.Get("/api/matches?state=done")).Body.GetProperty("matches")[0];
            Assert.False(old.Replays.ContainsKey(next.GetProperty("id").GetInt64()));
            Assert.True(next.TryGetProperty("score", out _), next.GetRawText()); // played, not forfeited
        }
    }

    // Turns the folder back into the older version's: files where it kept them, its schema version 2.
    private (Dictionary<long, byte[]> Submissions, Dictionary<long, byte[]> Replays) Downgrade()
    {
        var submissions = new Dictionary<long, byte[]>();
        var replays = new Dictionary<long, byte[]>();
        using (var store = SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db")))
        using (var c = new SqliteConnection(new SqliteConnectionStringBuilder { DataSource = Path.Combine(_folder, "ladder.db"), Pooling = false }.ToString()))
        {
            c.Open();
            foreach (var s in store.Submissions(null))
            {
                var file = store.SubmissionFiles(s.Id).Single();
                string folder = Path.Combine(_folder, "submissions", s.Id.ToString(System.Globalization.CultureInfo.InvariantCulture));
                Directory.CreateDirectory(folder);
                File.WriteAllBytes(Path.Combine(folder, file.Name), file.Bytes);
                Directory.Delete(Path.GetDirectoryName(s.Path)!, recursive: true);
                Sql(c, $"UPDATE submissions SET path = '{Path.Combine(folder, file.Name)}' WHERE id = {s.Id}");
                submissions[s.Id] = file.Bytes;
            }

            foreach (var m in store.Matches(1, [MatchRow.Done], 1000))
            {
                foreach (var (name, _) in store.MatchFileHashes(m.Id))
                {
                    var file = store.MatchFile(m.Id, name)!;
                    string path = name == LadderFiles.Replay ? Path.Combine(_folder, "replays", $"match-{m.Id}.html") : Path.Combine(_folder, "outputs", $"match-{m.Id}.json");
                    File.WriteAllBytes(path, file.Bytes);
                    if (name == LadderFiles.Replay)
                    {
                        replays[m.Id] = file.Bytes;
                    }
                }

                foreach (string copy in Directory.GetFiles(Path.Combine(_folder, "replays"), $"match-{m.Id}-*").Concat(Directory.GetFiles(Path.Combine(_folder, "outputs"), $"match-{m.Id}-*")))
                {
                    File.Delete(copy);
                }
            }

            Sql(c, "DROP TABLE match_files");
            Sql(c, "DROP TABLE submission_files");
            Sql(c, "DELETE FROM schema_version WHERE version > 2");
        }

        SqliteConnection.ClearAllPools();
        return (submissions, replays);
    }

    private static void Sql(SqliteConnection c, string sql)
    {
        using var command = c.CreateCommand();
        command.CommandText = sql;
        command.ExecuteNonQuery();
    }
}
