using System;
using System.Collections.Concurrent;
using System.Linq;
using System.Threading;
using Hangfire;
using Hangfire.Common;
using Hangfire.PostgreSql;
using Hangfire.PostgreSql.Factories;
using Hangfire.Server;
using Hangfire.States;
using Npgsql;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder;

/// <summary>
/// Matches shared between processes through Hangfire over the ladder's PostgreSQL database (its
/// tables in the schema <c>ladder_jobs</c>): the service queues one background job per match to play
/// on the queue <c>ladder</c>; every process with a Hangfire server on that queue (the service with
/// <c>--workers N</c> above 0, each <c>ladder worker</c>) takes jobs and plays their matches. Hangfire
/// gives a job to one server at a time, and to another when its server stops answering (the job's
/// invisibility, renewed while it runs every fifth of it, lapses the takeover time after a <c>kill -9</c>:
/// <see cref="Takeover"/>). A match is claimed for its job and its record written only while it is running,
/// so a match played twice is written once.
/// </summary>
internal sealed class LadderJobs : IDisposable
{
    /// <summary>The Hangfire queue of the ladder's matches.</summary>
    public const string Queue = "ladder";

    /// <summary>The takeover time unless <c>ladder serve --takeover</c> set another.</summary>
    public static TimeSpan DefaultTakeover => TimeSpan.FromMinutes(1);

    private const string TakeoverSetting = "takeover_seconds";

    /// <summary>
    /// How long a match taken by a process that stopped answering (its renewals of the job stopped) waits
    /// before another process plays it: <paramref name="given"/> (the service's <c>--takeover</c>), kept in the
    /// database so that every process that starts later uses the same (a process that waited less than
    /// another renews would take its matches while it plays them); else the one kept there; else a minute.
    /// </summary>
    public static TimeSpan Takeover(ILadderStore store, TimeSpan? given)
    {
        if (given is { } set)
        {
            store.SetSetting(TakeoverSetting, ((int)set.TotalSeconds).ToString(System.Globalization.CultureInfo.InvariantCulture));
            return set;
        }

        return store.Setting(TakeoverSetting) is { } kept && int.TryParse(kept, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out int seconds)
            && seconds is >= LadderSettings.MinTakeoverSeconds and <= LadderSettings.MaxTakeoverSeconds
            ? TimeSpan.FromSeconds(seconds)
            : DefaultTakeover;
    }

    private readonly PostgreSqlStorage _storage;
    private readonly BackgroundJobClient _client;
    private readonly string _connection;
    private readonly TimeSpan _invisibility;
    private BackgroundJobServer? _server;

    /// <summary>Hangfire's storage in the database <paramref name="connection"/> names (its tables made on first use).</summary>
    public LadderJobs(string connection, TimeSpan invisibility)
    {
        var options = new PostgreSqlStorageOptions
        {
            SchemaName = "ladder_jobs",
            PrepareSchemaIfNecessary = true,
            UseSlidingInvisibilityTimeout = true,
            InvisibilityTimeout = invisibility,
            QueuePollInterval = TimeSpan.FromSeconds(1),
        };
        _storage = new PostgreSqlStorage(new NpgsqlConnectionFactory(connection, options), options);
        _client = new BackgroundJobClient(_storage);
        _connection = connection;
        _invisibility = invisibility;
    }

    /// <summary>
    /// Whether a job on the ladder's queue waits to be taken over: its process took it and then stopped
    /// renewing it longer than the takeover time ago. Hangfire hands out the jobs nobody took before such
    /// a job, so it is played again only once the queue holds no untaken job: the matchmaker makes no
    /// new match while this is true.
    /// </summary>
    public bool TakeoverWaiting()
    {
        using var connection = new NpgsqlConnection(_connection);
        connection.Open();
        using var command = new NpgsqlCommand(
            "SELECT EXISTS (SELECT 1 FROM ladder_jobs.jobqueue WHERE queue = @queue AND fetchedat < NOW() - make_interval(secs => @seconds))",
            connection);
        command.Parameters.AddWithValue("queue", Queue);
        command.Parameters.AddWithValue("seconds", _invisibility.TotalSeconds);
        return command.ExecuteScalar() is true;
    }

    /// <summary>Queues the job that plays match <paramref name="match"/>; its id.</summary>
    public string Enqueue(long match) => _client.Create(Job.FromExpression<MatchJob>(j => j.Play(match, null!)), new EnqueuedState(Queue));

    /// <summary>Worker threads of every Hangfire server on the ladder's queue (live, or stopped less than Hangfire's server time-out ago).</summary>
    public int Workers() => _storage.GetMonitoringApi().Servers().Where(s => s.Queues.Contains(Queue)).Sum(s => s.WorkersCount);

    /// <summary>Starts this process's Hangfire server: <paramref name="workers"/> matches at once, each played by <paramref name="job"/>.</summary>
    public void Serve(int workers, MatchJob job)
    {
        _server = new BackgroundJobServer(
            new BackgroundJobServerOptions
            {
                WorkerCount = workers,
                Queues = [Queue],
                Activator = new OneJob(job),
                ServerName = $"ladder-{Environment.MachineName}-{Environment.ProcessId}",

                // On Ctrl+C the matches being played finish first (a match lasts minutes).
                ShutdownTimeout = TimeSpan.FromMinutes(30),
            },
            _storage);
    }

    /// <summary>Stops this process's server: the matches it plays finish first.</summary>
    public void Dispose() => _server?.Dispose();

    // Hangfire makes the job's object through this: always the one given.
    private sealed class OneJob(MatchJob job) : JobActivator
    {
        public override object ActivateJob(Type jobType) => jobType == typeof(MatchJob) ? job : base.ActivateJob(jobType);
    }
}

/// <summary>
/// The background job that plays one match of the ladder, in whichever process's Hangfire server takes
/// it: it claims the match for itself (nothing when the match is done, dropped, or another job's),
/// plays it from its seed and writes its record once.
/// </summary>
public sealed class MatchJob
{
    private readonly ILadderStore _store;
    private readonly Func<long, LadderCore> _coreOf;
    private readonly Action<long, bool> _told;
    private int _played;

    internal MatchJob(ILadderStore store, Func<long, LadderCore> coreOf, Action<long, bool> told)
    {
        _store = store;
        _coreOf = coreOf;
        _told = told;
    }

    /// <summary>Matches this process played and wrote.</summary>
    public int Played => Volatile.Read(ref _played);

    /// <summary>Plays match <paramref name="match"/> (Hangfire calls this; <paramref name="context"/> names the job).</summary>
    [AutomaticRetry(Attempts = 10)]
    public void Play(long match, PerformContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        if (_store.Match(match) is not { } row || !_store.ClaimForJob(match, context.BackgroundJob.Id))
        {
            return;
        }

        _told(match, false);
        if (_coreOf(row.LadderId).Play(_store.Match(match)!))
        {
            Interlocked.Increment(ref _played);
            _told(match, true);
        }
    }

    /// <summary>A job of the cores of the ladders (made once each, as players, the first time one of its matches comes) over <paramref name="store"/>.</summary>
    internal static MatchJob Of(ILadderStore store, LadderSettings settings, LadderCore? own, Action<long, bool> told)
    {
        var cores = new ConcurrentDictionary<long, Lazy<LadderCore>>();
        if (own is not null)
        {
            cores[own.LadderId] = new Lazy<LadderCore>(own);
        }

        return new MatchJob(store, id => cores.GetOrAdd(id, _ => new Lazy<LadderCore>(() => LadderCore.Player(store, settings, store.Ladder(id)!))).Value, told);
    }
}
