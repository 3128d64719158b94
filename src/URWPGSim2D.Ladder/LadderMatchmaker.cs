using System;
using System.Threading;

namespace URWPGSim2D.Ladder;

/// <summary>
/// The service's matchmaking when matches are played through Hangfire (PostgreSQL): one thread that
/// keeps, in each ladder, twice as many matches waiting as there are worker threads on the ladders'
/// queue (at least two: a worker finds its next match waiting when it ends one, though the matches of
/// other processes end unseen), making them one ladder after the other so that the queue serves every
/// ladder in turn; it hands each new match to a job, and hands to a job every queued match that has
/// none (one made just before the service stopped, a requeued one, the final round's). While a dead
/// worker's job waits to be taken over it makes no new match, so that the queue empties down to that
/// job (<see cref="LadderJobs.TakeoverWaiting"/>). It looks again when a ladder changes and every half
/// second (workers in other processes finish matches).
/// </summary>
internal sealed class LadderMatchmaker : IDisposable
{
    private readonly LadderService _service;
    private readonly LadderJobs _jobs;
    private readonly Action<string> _report;
    private readonly Thread _thread;
    private readonly CancellationTokenSource _stop = new();
    private readonly SemaphoreSlim _wake = new(0, int.MaxValue);

    public LadderMatchmaker(LadderService service, LadderJobs jobs, Action<string> report)
    {
        _service = service;
        _jobs = jobs;
        _report = report;
        service.Changed += Wake;
        _thread = new Thread(Loop) { IsBackground = true, Name = "ladder matchmaker" };
    }

    public void Start() => _thread.Start();

    private void Wake() => _wake.Release();

    private void Loop()
    {
        while (!_stop.IsCancellationRequested)
        {
            try
            {
                Schedule();
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                _report($"ladder: matchmaking failed: {e.GetType().Name}: {e.Message.ReplaceLineEndings(" ")}");
            }

            try
            {
                _wake.Wait(TimeSpan.FromSeconds(0.5), _stop.Token);
            }
            catch (OperationCanceledException)
            {
                return;
            }
        }
    }

    private void Schedule()
    {
        var store = _service.Store;
        var cores = _service.Cores();
        foreach (var core in cores)
        {
            foreach (long id in store.Unscheduled(core.LadderId))
            {
                store.SetJob(id, _jobs.Enqueue(id));
            }
        }

        if (_jobs.TakeoverWaiting())
        {
            return;
        }

        int waiting = 2 * Math.Max(1, _jobs.Workers());
        for (bool made = true; made && !_stop.IsCancellationRequested;)
        {
            made = false;
            foreach (var core in cores)
            {
                if (core.MakeMatch(waiting) is { } match)
                {
                    store.SetJob(match.Id, _jobs.Enqueue(match.Id));
                    made = true;
                }
            }
        }
    }

    public void Dispose()
    {
        _service.Changed -= Wake;
        _stop.Cancel();
        if (_thread.IsAlive)
        {
            _thread.Join();
        }

        _stop.Dispose();
        _wake.Dispose();
    }
}
