namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// The store, the same tests on SQLite and on a real PostgreSQL server: migrations run once, a
/// match's record is written once, a stopped service's running matches go back to the queue.
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
}
