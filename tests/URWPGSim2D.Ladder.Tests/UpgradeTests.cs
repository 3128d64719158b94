using Microsoft.Data.Sqlite;

namespace URWPGSim2D.Ladder.Tests;

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
            Sql(c, "DROP INDEX submissions_ladder"); // and the ladder of each submission and house entrant (version 4)
            Sql(c, "ALTER TABLE submissions DROP COLUMN ladder_id");
            Sql(c, "ALTER TABLE teams DROP COLUMN ladder_id");
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
