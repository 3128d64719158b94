namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// The store, the same tests on SQLite and on a real PostgreSQL server: migrations run once, a
/// match's record is written once, a stopped service's running matches go back to the queue; a
/// match's files are written with its record, once, and dropped by a requeue; a submission's files
/// come back byte for byte, so a second data folder (another machine's) plays a submission and reads
/// a match's outputs from the database alone.
/// </summary>
[Collection(PostgresCollection.Name)]
public sealed class StoreTests(PostgresServer postgres) : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-store-").FullName;
    private readonly List<SqlLadderStore> _stores = [];

    public void Dispose()
    {
        foreach (var s in _stores)
        {
            s.Dispose();
        }

        Directory.Delete(_folder, recursive: true);
    }

    // A new store of the database: sqlite (a file) or postgresql (a new database on the server).
    private SqlLadderStore Store(string database)
    {
        var store = database == "sqlite" ? SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db")) : SqlDialect.PostgreSqlStore(postgres.NewDatabase());
        _stores.Add(store);
        store.Migrate();
        return store;
    }

    // A store with a ladder of seed base 7 and two house teams.
    private (SqlLadderStore Store, LadderRow Ladder, TeamRow A, TeamRow B) Two(string database)
    {
        var store = Store(database);
        var ladder = store.OpenLadder("polo-1v1", 600, 7);
        return (store, ladder, store.AddTeam("a", "ha", "demo", ladder.Id)!, store.AddTeam("b", "hb", "idle", ladder.Id)!);
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void MigrationsRunOnceAndKeepTheRows(string database)
    {
        var store = Store(database);
        Assert.Equal(database, store.Dialect.Name);
        Assert.Equal(store.Dialect.Migrations.Count, store.SchemaVersion());
        Assert.NotNull(store.AddTeam("alpha", "hash-a", null, 0));
        store.Migrate(); // a second start: nothing runs again, nothing is lost
        Assert.Equal(store.Dialect.Migrations.Count, store.SchemaVersion());
        Assert.Equal(["alpha"], store.Teams().Select(t => t.Name));
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void ATeamNameIsTakenOnce(string database)
    {
        var store = Store(database);
        Assert.NotNull(store.AddTeam("alpha", "hash-a", null, 0));
        Assert.Null(store.AddTeam("alpha", "hash-b", "demo", 0));
        Assert.Equal("hash-a", store.TeamByName("alpha")!.TokenHash);
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void AMatchIsClaimedOnceAndItsRecordWrittenOnce(string database)
    {
        var (store, ladder, a, b) = Two(database);
        var queued = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], final: false, id => 100 + (ulong)id);
        Assert.Equal(100 + (ulong)queued.Id, queued.Seed);

        var claimed = store.ClaimNext(ladder.Id);
        Assert.Equal(queued.Id, claimed!.Id);
        Assert.Null(store.ClaimNext(ladder.Id)); // nothing else waits
        Assert.True(store.FinishMatch(claimed.Id, "{\"first\":1}"));
        Assert.False(store.FinishMatch(claimed.Id, "{\"second\":2}")); // written once
        Assert.Equal("{\"first\":1}", Assert.Single(store.Records(ladder.Id)).Record);
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void RunningMatchesGoBackToTheQueueWithTheirSeed(string database)
    {
        var (store, ladder, a, b) = Two(database);
        var m = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], final: false, id => 7 + (ulong)id);
        Assert.True(store.Claim(m.Id));

        Assert.Equal(1, store.RequeueRunning());
        var again = store.ClaimNext(ladder.Id)!;
        Assert.Equal((m.Id, m.Seed, MatchRow.Running), (again.Id, again.Seed, again.State));
        Assert.Empty(store.Records(ladder.Id));
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void ARequeuedMatchLosesItsRecordAndWaitsAgain(string database)
    {
        var (store, ladder, a, b) = Two(database);
        var m = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], final: false, id => 7 + (ulong)id);
        Assert.False(store.Requeue(m.Id)); // not finished yet
        store.Claim(m.Id);
        store.FinishMatch(m.Id, "{}");
        Assert.True(store.Requeue(m.Id));
        Assert.Equal(MatchRow.Queued, store.Match(m.Id)!.State);
        Assert.Null(store.Match(m.Id)!.Record);
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void GamesCountEachSideOfEveryMatch(string database)
    {
        var (store, ladder, a, b) = Two(database);
        var c = store.AddTeam("c", "hc", "idle", ladder.Id)!;
        store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], false, id => (ulong)id);
        store.AddMatch(ladder.Id, [a.Id, c.Id], [0, 0], false, id => (ulong)id);
        var games = store.Games(ladder.Id);
        Assert.Equal((2, 1, 1), (games[a.Id], games[b.Id], games[c.Id]));
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void ClaimersAtOnceTakeEachMatchOnce(string database)
    {
        var (store, ladder, a, b) = Two(database);
        var ids = Enumerable.Range(0, 40).Select(_ => store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], false, id => (ulong)id).Id).ToList();

        // Four claimers at once until the queue is empty, each call on a connection of its own (as processes would be).
        var claimed = new System.Collections.Concurrent.ConcurrentBag<long>();
        System.Threading.Tasks.Parallel.For(0, 4, new System.Threading.Tasks.ParallelOptions { MaxDegreeOfParallelism = 4 }, _ =>
        {
            while (store.ClaimNext(ladder.Id) is { } m)
            {
                claimed.Add(m.Id);
            }
        });

        Assert.Equal(ids.Order(), claimed.Order());
    }

    [Theory]
    [InlineData("sqlite")]
    [InlineData("postgresql")]
    public void AFinalRoundDropsTheWaitingRankedMatchesAndStartsOnce(string database)
    {
        var (store, ladder, a, b) = Two(database);
        var played = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], false, id => (ulong)id);
        store.Claim(played.Id);
        store.FinishMatch(played.Id, "{}");
        store.AddMatch(ladder.Id, [b.Id, a.Id], [0, 0], false, id => (ulong)id); // waiting: dropped

        Assert.True(store.StartFinal(ladder.Id, [(a.Id, b.Id, 0, 0), (b.Id, a.Id, 0, 0)], id => 1000 + (ulong)id));
        Assert.False(store.StartFinal(ladder.Id, [(a.Id, b.Id, 0, 0)], id => (ulong)id)); // once
        var final = store.FinalMatches(ladder.Id);
        Assert.Equal([(true, MatchRow.Queued), (true, MatchRow.Queued)], final.Select(m => (m.Final, m.State)));
        Assert.All(final, m => Assert.Equal(1000 + (ulong)m.Id, m.Seed));
        Assert.Equal([played.Id, .. final.Select(m => m.Id)], store.Matches(ladder.Id, [], 100).Select(m => m.Id).Order());
        Assert.Equal(final[0].Id, store.ClaimNext(ladder.Id)!.Id);
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
        var a = store.AddTeam("a", "ha", "demo", ladder.Id)!;
        var b = store.AddTeam("b", "hb", "idle", ladder.Id)!;
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
        var ladder = store.OpenLadder("polo-1v1", 600, 7);
        var team = store.AddTeam("coder", "hc", null, 0)!;
        var row = store.AddSubmission(team.Id, ladder.Id, "upload", DateTime.UtcNow);

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
        var house = store.AddTeam("house", "hh", "idle", ladder.Id)!;
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
