using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// <c>kill -9</c> of the service while a match is being played loses and doubles nothing: on the
/// next start the match is played again from its seed, its record written once, and every match
/// made before the kill is still there.
/// </summary>
public sealed class RestartTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-kill-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private const string Admin = "organiser-restart";

    private Task<ServeProcess> Serve() =>
        ServeProcess.StartAsync("ladder", "serve", "--item", "polo-1v1", "--minutes", "10", "--data", _folder, "--port", "0", "--admin-token", Admin);

    private SqlLadderStore Store() => SqlDialect.SqliteStore(Path.Combine(_folder, "ladder.db"));

    [Fact]
    public async Task KillNineMidMatchLosesAndDoublesNothing()
    {
        // Kill while a match runs (ten-minute matches: most of the time one does); if the kill lands
        // between two matches, start again and kill again.
        MatchRow? interrupted = null;
        for (int attempt = 0; attempt < 10 && interrupted is null; attempt++)
        {
            using var serve = await Serve();
            if (attempt == 0)
            {
                using var organiser = new LadderClient(serve.Url, Admin);
                await organiser.AddTeamAsync("strong", "demo");
                await organiser.AddTeamAsync("weak", "idle");
            }

            var store = Store();
            await LadderHost.Until(() => Task.FromResult(store.Records(1).Count >= 2 * (attempt + 1) && store.Matches(1, [MatchRow.Running], 1).Count == 1), "two more matches played and one running");
            serve.KillHard();
            interrupted = store.Matches(1, [MatchRow.Running], 1).SingleOrDefault();
        }

        Assert.NotNull(interrupted);
        var before = Store().Matches(1, [], 10_000).ToDictionary(m => m.Id);
        var recordsBefore = Store().Records(1).ToDictionary(r => r.Id, r => r.Record);

        using (var again = await Serve())
        {
            var store = Store();
            await LadderHost.Until(() => Task.FromResult(store.Match(interrupted.Id)!.State == MatchRow.Done && store.Records(1).Count >= recordsBefore.Count + 2), "the interrupted match and one more played");
            again.KillHard();
        }

        var after = Store().Matches(1, [], 10_000).ToDictionary(m => m.Id);
        var records = Store().Records(1);

        // Nothing lost: every match made before the kill is still there, with its seed and sides; what was finished kept its record.
        foreach (var (id, m) in before)
        {
            Assert.Equal((m.Seed, m.Teams[0], m.Teams[1]), (after[id].Seed, after[id].Teams[0], after[id].Teams[1]));
        }

        foreach (var (id, record) in recordsBefore)
        {
            Assert.Equal(record, records.Single(r => r.Id == id).Record);
        }

        // Nothing doubled: one record per match id, each for its own match and seed.
        Assert.Equal(records.Count, records.Select(r => r.Id).Distinct().Count());
        foreach (var (id, line, _) in records)
        {
            var r = TournamentFile.ParseRecord(line);
            Assert.Equal((id, after[id].Seed), (r.Index, r.Seed));
        }

        // The interrupted match was played again from its seed: the same result a second play of that seed gives.
        var replayed = TournamentFile.ParseRecord(records.Single(r => r.Id == interrupted.Id).Record);
        Assert.NotNull(replayed.Result);
        Assert.Equal(interrupted.Seed, replayed.Seed);
    }
}
