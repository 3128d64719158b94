using System;
using System.IO;

namespace URWPGSim2D.Ladder;

/// <summary>
/// <c>urwpgsim2d ladder worker</c>: a process that plays the ladder's matches beside the service,
/// on this machine or another: it takes the matches the service queues in the PostgreSQL database
/// (Hangfire jobs, <see cref="LadderSettings.Database"/>) and writes their records and outputs there. It
/// needs nothing of the service's but the database: submissions come from the database and are copied into
/// its own data folder (kept between starts, so a submission is fetched once), where it also plays replay
/// pages before they go to the database with the match's record.
/// </summary>
public sealed class LadderWorker : IDisposable
{
    private readonly Storage.ILadderStore _store;
    private readonly LadderJobs _jobs;
    private readonly MatchJob _job;

    private LadderWorker(Storage.ILadderStore store, LadderJobs jobs, MatchJob job)
    {
        _store = store;
        _jobs = jobs;
        _job = job;
    }

    /// <summary>Matches this worker played.</summary>
    public int Played => _job.Played;

    /// <summary>Starts playing: <see cref="LadderSettings.Workers"/> matches at once.</summary>
    /// <param name="settings">The database (required), the data folder (this worker's copies), the number of matches at once, how strategies run.</param>
    /// <param name="told">Told each match's id when it starts (false) and when this worker wrote its record (true).</param>
    /// <exception cref="LadderInputException">No database is given, it cannot be reached, or it has no ladder yet (the message says which).</exception>
    public static LadderWorker Start(LadderSettings settings, Action<long, bool> told)
    {
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentNullException.ThrowIfNull(told);
        if (settings.Database is null)
        {
            throw new LadderInputException("--database: a worker needs the service's PostgreSQL database");
        }

        if (settings.Workers < 1)
        {
            throw new LadderInputException($"--workers must be 1 or more for a worker, got {settings.Workers}");
        }

        var store = LadderDatabase.Open(settings);
        if (store.NewestLadder() is null)
        {
            store.Dispose();
            throw new LadderInputException("--database: the database has no ladder yet; start ladder serve with it first");
        }

        Directory.CreateDirectory(settings.DataDir);
        var jobs = new LadderJobs(settings.Database, LadderJobs.Takeover(store, null));
        var job = MatchJob.Of(store, settings, null, told);
        jobs.Serve(settings.Workers, job);
        return new LadderWorker(store, jobs, job);
    }

    /// <summary>Stops taking matches; the matches being played finish first.</summary>
    public void Dispose()
    {
        _jobs.Dispose();
        _store.Dispose();
    }
}
