using System.Diagnostics;
using System.Text.RegularExpressions;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// Two <c>ladder worker</c> processes beside a service that plays nothing itself, on a real
/// PostgreSQL server, each with a data folder of its own (as on other machines): both play matches,
/// a team's uploaded submission among them, and the service shows their results, replay pages and the
/// team's logs; one worker is killed with SIGKILL in the middle of a match, which the other then plays
/// from its seed once the service's takeover time has passed; every match is written once, by the one
/// process that says so.
/// </summary>
[Collection(PostgresCollection.Name)]
public sealed partial class WorkerTests(PostgresServer postgres) : IDisposable
{
    private const string Admin = "organiser-workers";

    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-workers-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public async Task TwoWorkersShareTheMatchesAndAKilledWorkersMatchIsPlayedOnceByTheOther()
    {
        string database = postgres.NewDatabase();
        string service = Path.Combine(_folder, "service");
        using var serve = await ServeProcess.StartAsync("ladder", "serve", "--item", "polo-1v1", "--minutes", "1", "--data", service, "--database", database,
            "--port", "0", "--admin-token", Admin, "--workers", "0", "--takeover", "10");
        string coder;
        using (var organiser = new LadderClient(serve.Url, Admin))
        {
            await organiser.AddTeamAsync("strong", "demo");
            await organiser.AddTeamAsync("weak", "idle");
            await organiser.AddTeamAsync("chaser", "chase-ball");
            coder = (await organiser.AddTeamAsync("coder", null)).Token;
        }

        string source = Path.Combine(_folder, "Still.cs");
        File.WriteAllText(source, URWPGSim2D.Testing.SdkStrategy.Source("Still", "still", "d.Fill(Decision.Stop);"));
        using (var team = new LadderClient(serve.Url, coder))
        {
            Assert.True((await team.SubmitAsync(source)).Ok);
        }

        // Each worker's folder is its own, none the service's.
        int folders = 0;
        string Folder() => Path.Combine(_folder, "worker-" + (++folders).ToString(System.Globalization.CultureInfo.InvariantCulture));
        var gone = new List<WorkerProcess>();
        using var b = WorkerProcess.Start(database, Folder());
        var a = WorkerProcess.Start(database, Folder());
        try
        {
            // Kill a while it plays a match, once it has played one (if a kill lands after the match was written, start it again and kill again).
            using var store = SqlDialect.PostgreSqlStore(database);
            long interrupted = 0;
            for (int attempt = 0; attempt < 10 && interrupted == 0; attempt++)
            {
                await LadderHost.Until(() => Task.FromResult(a.Written.Count >= 1 || attempt > 0), "worker a wrote a match");
                long killed = await a.KillWhenPlaying();
                gone.Add(a);
                if (store.Match(killed)!.State == MatchRow.Running)
                {
                    interrupted = killed;
                }
                else
                {
                    a = WorkerProcess.Start(database, Folder());
                }
            }

            Assert.NotEqual(0, interrupted);

            // The other worker plays it, once the job's renewals from the killed one have lapsed (the service's --takeover).
            await LadderHost.Until(() => Task.FromResult(b.Written.Contains(interrupted)), $"worker b played match {interrupted}", minutes: 6);
            Assert.Equal(MatchRow.Done, store.Match(interrupted)!.State);

            // The service shows what the workers played: every played match's replay page, and the team's own logs.
            long coderId = store.TeamByName("coder")!.Id;
            await LadderHost.Until(() => Task.FromResult(store.Records(1).Count(r => TeamsOf(store, r.Id).Contains(coderId)) >= 2), "the submission played twice", minutes: 6);
            b.KillHard();
            using var http = new HttpClient { BaseAddress = new Uri(serve.Url) };
            var done = JsonDocument.Parse(await http.GetStringAsync("/api/matches?state=done&limit=1000")).RootElement.GetProperty("matches").EnumerateArray().ToList();
            Assert.Contains(done, m => m.GetProperty("id").GetInt64() == interrupted);
            foreach (var m in done.Where(m => m.TryGetProperty("score", out _)))
            {
                string page = await http.GetStringAsync(m.GetProperty("replay").GetString());
                Assert.Contains("<html", page, StringComparison.OrdinalIgnoreCase);
                long id = m.GetProperty("id").GetInt64();
                if (TeamsOf(store, id).Contains(coderId))
                {
                    using var log = new HttpRequestMessage(HttpMethod.Get, $"/api/teams/coder/matches/{id}/log");
                    log.Headers.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", coder);
                    using var answer = await http.SendAsync(log);
                    Assert.Equal(System.Net.HttpStatusCode.OK, answer.StatusCode);
                }
            }

            Assert.Contains(done, m => m.GetProperty("teams").EnumerateArray().Any(t => t.GetString() == "coder") && m.TryGetProperty("score", out _)); // played, not forfeited
            serve.KillHard();

            // Both played; each match written by exactly one process, which said so; nothing written twice or without its match.
            var written = gone.SelectMany(g => g.Written).Concat(b.Written).ToList();
            Assert.NotEmpty(gone[0].Written);
            Assert.NotEmpty(b.Written);
            Assert.Equal(written.Count, written.Distinct().Count());
            var records = store.Records(1);
            var recorded = records.Select(r => r.Id).ToHashSet();
            Assert.Equal(records.Count, recorded.Count);
            Assert.Subset(recorded, written.ToHashSet()); // nothing said written is lost
            var mayBeUnsaid = b.Playing.Except(b.Written).ToHashSet(); // b killed between writing a match and saying so
            Assert.Subset(written.Concat(mayBeUnsaid).ToHashSet(), recorded); // nothing written but by a process that plays it
            foreach (var (id, line, _) in records)
            {
                var r = TournamentFile.ParseRecord(line);
                Assert.Equal((id, store.Match(id)!.Seed), (r.Index, r.Seed));
                Assert.NotNull(r.Result);
            }
        }
        finally
        {
            foreach (var g in gone.Append(a).Distinct())
            {
                g.Dispose();
            }
        }
    }

    private static IReadOnlyList<long> TeamsOf(SqlLadderStore store, long match) => store.Match(match)!.Teams;

    [Fact]
    public async Task AWorkerOfADatabaseWithoutALadderIsOneLineAndExitTwo()
    {
        var (code, output, error) = await ServeProcess.RunAsync("ladder", "worker", "--database", postgres.NewDatabase(), "--data", _folder);
        Assert.Equal((2, string.Empty), (code, output));
        Assert.Equal("ladder worker: --database: the database has no ladder yet; start ladder serve with it first\n", error);
    }

    [GeneratedRegex(@"^ladder worker: (playing match|match) (\d+)( played)?$")]
    private static partial Regex MatchLine();

    /// <summary><c>ladder worker</c> as its own process, each line of its output read as it comes.</summary>
    private sealed class WorkerProcess : IDisposable
    {
        private readonly Process _process;
        private readonly object _gate = new();
        private readonly List<long> _playing = [];
        private readonly List<long> _written = [];
        private TaskCompletionSource<long>? _killOnPlaying;

        private WorkerProcess(Process process) => _process = process;

        /// <summary>The matches it started, in order.</summary>
        public IReadOnlyList<long> Playing
        {
            get
            {
                lock (_gate)
                {
                    return [.. _playing];
                }
            }
        }

        /// <summary>The matches it said it wrote, in order.</summary>
        public IReadOnlyList<long> Written
        {
            get
            {
                lock (_gate)
                {
                    return [.. _written];
                }
            }
        }

        public static WorkerProcess Start(string database, string data)
        {
            var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in new[] { ServeProcess.ServerDll, "ladder", "worker", "--database", database, "--data", data })
            {
                start.ArgumentList.Add(a);
            }

            var worker = new WorkerProcess(Process.Start(start)!);
            worker._process.OutputDataReceived += (_, e) => worker.Line(e.Data);
            worker._process.ErrorDataReceived += (_, _) => { };
            worker._process.BeginOutputReadLine();
            worker._process.BeginErrorReadLine();
            return worker;
        }

        // A match's line: noted; the first "playing" line after KillWhenPlaying kills the process at once.
        private void Line(string? line)
        {
            if (line is null || MatchLine().Match(line) is not { Success: true } m)
            {
                return;
            }

            long id = long.Parse(m.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture);
            TaskCompletionSource<long>? kill = null;
            lock (_gate)
            {
                (m.Groups[3].Success ? _written : _playing).Add(id);
                if (!m.Groups[3].Success && _killOnPlaying is { } k)
                {
                    kill = k;
                    _killOnPlaying = null;
                }
            }

            if (kill is not null)
            {
                // SIGKILL now; waiting for the exit is the caller's (this thread reads the output the wait waits for).
                _process.Kill(entireProcessTree: false);
                kill.SetResult(id);
            }
        }

        /// <summary>SIGKILL as soon as it starts its next match; that match's id.</summary>
        public Task<long> KillWhenPlaying()
        {
            var kill = new TaskCompletionSource<long>(TaskCreationOptions.RunContinuationsAsynchronously);
            lock (_gate)
            {
                _killOnPlaying = kill;
            }

            return Killed(kill.Task);
        }

        private async Task<long> Killed(Task<long> kill)
        {
            long id = await kill.WaitAsync(TimeSpan.FromMinutes(5));
            await _process.WaitForExitAsync();
            return id;
        }

        /// <summary>SIGKILL, and waits until the process is gone.</summary>
        public void KillHard()
        {
            if (!_process.HasExited)
            {
                _process.Kill(entireProcessTree: false);
            }

            _process.WaitForExit();
        }

        public void Dispose() => ServeProcess.End(_process);
    }
}
