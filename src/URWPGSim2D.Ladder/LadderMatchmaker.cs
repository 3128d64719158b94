using System;
using System.Threading;

namespace URWPGSim2D.Ladder;

/// <summary>
/// The service's matchmaking when matches are played through Hangfire (PostgreSQL): one thread that
/// keeps as many matches waiting as there are worker threads on the ladder's queue (at least one),
/// hands each new match to a job, and hands to a job every queued match that has none (one made just
/// before the service stopped, a requeued one, the final round's). It looks again when the ladder
/// changes and every two seconds (workers in other processes finish matches).
/// </summary>
internal sealed class LadderMatchmaker : IDisposable
{
    private readonly LadderCore _core;
    private readonly LadderJobs _jobs;
    private readonly Action<string> _report;
    private readonly Thread _thread;
    private readonly CancellationTokenSource _stop = new();
    private readonly SemaphoreSlim _wake = new(0, int.MaxValue);

    public LadderMatchmaker(LadderCore core, LadderJobs jobs, Action<string> report)
    {
        _core = core;
        _jobs = jobs;
        _report = report;
        core.Changed += Wake;
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
                _wake.Wait(TimeSpan.FromSeconds(2), _stop.Token);
            }
            catch (OperationCanceledException)
            {
                return;
            }
        }
    }

    private void Schedule()
    {
        var store = _core.Store;
        foreach (long id in store.Unscheduled(_core.LadderId))
        {
            store.SetJob(id, _jobs.Enqueue(id));
        }

        int waiting = Math.Max(1, _jobs.Workers());
        while (!_stop.IsCancellationRequested && _core.MakeMatch(waiting) is { } match)
        {
            store.SetJob(match.Id, _jobs.Enqueue(match.Id));
        }
    }

    public void Dispose()
    {
        _core.Changed -= Wake;
        _stop.Cancel();
        if (_thread.IsAlive)
        {
            _thread.Join();
        }

        _stop.Dispose();
        _wake.Dispose();
    }
}
