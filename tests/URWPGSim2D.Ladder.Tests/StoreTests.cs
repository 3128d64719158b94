using System;
using System.IO;
using System.Linq;
using URWPGSim2D.Ladder.Storage;
using Xunit;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>The SQLite store: migrations run once, a match's record is written once, a stopped service's running matches go back to the queue.</summary>
public sealed class StoreTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-store-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private SqlLadderStore Store()
    {
        var store = SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db"));
        store.Migrate();
        return store;
    }

    // A store with a ladder of seed base 7 and two house teams.
    private (SqlLadderStore Store, LadderRow Ladder, TeamRow A, TeamRow B) Two()
    {
        var store = Store();
        return (store, store.OpenLadder("polo-1v1", 600, 7), store.AddTeam("a", "ha", "demo")!, store.AddTeam("b", "hb", "idle")!);
    }

    [Fact]
    public void MigrationsRunOnceAndKeepTheRows()
    {
        var store = Store();
        Assert.Equal(SqlDialect.Sqlite.Migrations.Count, store.SchemaVersion());
        Assert.NotNull(store.AddTeam("alpha", "hash-a", null));
        store.Migrate(); // a second start: nothing runs again, nothing is lost
        Assert.Equal(SqlDialect.Sqlite.Migrations.Count, store.SchemaVersion());
        Assert.Equal(["alpha"], store.Teams().Select(t => t.Name));
    }

    [Fact]
    public void ATeamNameIsTakenOnce()
    {
        var store = Store();
        Assert.NotNull(store.AddTeam("alpha", "hash-a", null));
        Assert.Null(store.AddTeam("alpha", "hash-b", "demo"));
        Assert.Equal("hash-a", store.TeamByName("alpha")!.TokenHash);
    }

    [Fact]
    public void AMatchIsClaimedOnceAndItsRecordWrittenOnce()
    {
        var (store, ladder, a, b) = Two();
        var queued = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], final: false, id => 100 + (ulong)id);
        Assert.Equal(100 + (ulong)queued.Id, queued.Seed);

        var claimed = store.ClaimNext(ladder.Id);
        Assert.Equal(queued.Id, claimed!.Id);
        Assert.Null(store.ClaimNext(ladder.Id)); // nothing else waits
        Assert.True(store.FinishMatch(claimed.Id, "{\"first\":1}"));
        Assert.False(store.FinishMatch(claimed.Id, "{\"second\":2}")); // written once
        Assert.Equal("{\"first\":1}", Assert.Single(store.Records(ladder.Id)).Record);
    }

    [Fact]
    public void RunningMatchesGoBackToTheQueueWithTheirSeed()
    {
        var (store, ladder, a, b) = Two();
        var m = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], final: false, id => 7 + (ulong)id);
        Assert.True(store.Claim(m.Id));

        Assert.Equal(1, store.RequeueRunning());
        var again = store.ClaimNext(ladder.Id)!;
        Assert.Equal((m.Id, m.Seed, MatchRow.Running), (again.Id, again.Seed, again.State));
        Assert.Empty(store.Records(ladder.Id));
    }

    [Fact]
    public void ARequeuedMatchLosesItsRecordAndWaitsAgain()
    {
        var (store, ladder, a, b) = Two();
        var m = store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], final: false, id => 7 + (ulong)id);
        Assert.False(store.Requeue(m.Id)); // not finished yet
        store.Claim(m.Id);
        store.FinishMatch(m.Id, "{}");
        Assert.True(store.Requeue(m.Id));
        Assert.Equal(MatchRow.Queued, store.Match(m.Id)!.State);
        Assert.Null(store.Match(m.Id)!.Record);
    }

    [Fact]
    public void GamesCountEachSideOfEveryMatch()
    {
        var (store, ladder, a, b) = Two();
        var c = store.AddTeam("c", "hc", "idle")!;
        store.AddMatch(ladder.Id, [a.Id, b.Id], [0, 0], false, id => (ulong)id);
        store.AddMatch(ladder.Id, [a.Id, c.Id], [0, 0], false, id => (ulong)id);
        var games = store.Games(ladder.Id);
        Assert.Equal((2, 1, 1), (games[a.Id], games[b.Id], games[c.Id]));
    }
}
