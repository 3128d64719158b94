using System;
using System.Threading;

namespace URWPGSim2D.Ladder;

/// <summary>
/// The matchmaking loop that never stops: each worker thread claims the next match of the next ladder
/// in turn (queuing one when none waits) and plays it; with nothing to play it waits until the ladder changes (a team,
/// a submission, a resume, a requeue) or a minute passes (another process may have queued one).
/// A match that throws is the server's failure, already written as a forfeit of the side at fault;
/// anything thrown past that is reported and the loop goes on.
/// </summary>
internal sealed class LadderWorkers : IDisposable
{
    private readonly LadderService _core;
    private readonly Action<string> _report;
    private readonly Thread[] _threads;
    private readonly CancellationTokenSource _stop = new();
    private readonly SemaphoreSlim _wake = new(0, int.MaxValue);

    public LadderWorkers(LadderService core, int workers, Action<string> report)
    {
        _core = core;
        _report = report;
        _threads = new Thread[workers];
        core.Changed += Wake;
        for (int w = 0; w < workers; w++)
        {
            _threads[w] = new Thread(Loop) { IsBackground = true, Name = $"ladder worker {w + 1}" };
        }
    }

    /// <summary>Matches finished by these workers.</summary>
    public int Played => Volatile.Read(ref _played);

    private int _played;

    public void Start()
    {
        foreach (var t in _threads)
        {
            t.Start();
        }
    }

    public void Wake() => _wake.Release(Math.Max(1, _threads.Length));

    private void Loop()
    {
        while (!_stop.IsCancellationRequested)
        {
            bool played;
            try
            {
                played = _core.PlayNext();
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                _report($"ladder: a worker failed: {e.GetType().Name}: {e.Message.ReplaceLineEndings(" ")}");
                played = false;
            }

            if (played)
            {
                Interlocked.Increment(ref _played);
            }
            else
            {
                try
                {
                    _wake.Wait(TimeSpan.FromMinutes(1), _stop.Token);
                }
                catch (OperationCanceledException)
                {
                    return;
                }
            }
        }
    }

    public void Dispose()
    {
        _core.Changed -= Wake;
        _stop.Cancel();
        foreach (var t in _threads)
        {
            if (t.IsAlive)
            {
                t.Join();
            }
        }

        _stop.Dispose();
        _wake.Dispose();
    }
}
