using System;
using System.Threading;

namespace URWPGSim2D.Server.Strategies;

/// <summary>
/// Runs a strategy's <see cref="IStrategy.Decide"/> on a dedicated background thread and waits at
/// most a time limit for it. A late call is abandoned (its result is discarded when it finally
/// returns) and the strategy is skipped while it is still busy, so a strategy that hangs cannot
/// stop the match.
/// </summary>
internal sealed class IsolatedStrategyRunner
{
    private readonly IStrategy _strategy;
    private readonly Decision[] _work;
    private readonly SemaphoreSlim _start = new(0);
    private readonly SemaphoreSlim _done = new(0);
    private MatchSnapshot? _snapshot;
    private int[] _fish = [];
    private Exception? _error;
    private bool _pending;
    private volatile bool _stopped;

    public IsolatedStrategyRunner(IStrategy strategy, int fishCount, int team)
    {
        _strategy = strategy;
        _work = new Decision[fishCount];
        var thread = new Thread(Loop) { IsBackground = true, Name = $"strategy team {team}" };
        thread.Start();
    }

    /// <summary>Outcome of one call.</summary>
    public enum Outcome
    {
        /// <summary>Finished in time; decisions updated.</summary>
        Decided,

        /// <summary>Threw; decisions unchanged.</summary>
        Threw,

        /// <summary>Too slow or still busy; decisions unchanged.</summary>
        TimedOut,
    }

    /// <summary>Asks for decisions, waiting at most <paramref name="timeoutMs"/> ms.</summary>
    public Outcome Decide(MatchSnapshot snapshot, int[] fish, Span<Decision> decisions, int timeoutMs, out Exception? error)
    {
        error = null;
        if (_pending)
        {
            if (!_done.Wait(0))
            {
                return Outcome.TimedOut;
            }

            _pending = false;
        }

        decisions.CopyTo(_work);
        _snapshot = snapshot;
        _fish = fish;
        _error = null;
        _pending = true;
        _start.Release();
        if (!_done.Wait(timeoutMs))
        {
            return Outcome.TimedOut;
        }

        _pending = false;
        if (_error is not null)
        {
            error = _error;
            return Outcome.Threw;
        }

        _work.CopyTo(decisions);
        return Outcome.Decided;
    }

    /// <summary>Lets the strategy's thread end once its current call (if any) returns; the runner is not used afterwards.</summary>
    public void Stop()
    {
        _stopped = true;
        _start.Release();
    }

    private void Loop()
    {
        while (true)
        {
            _start.Wait();
            if (_stopped)
            {
                return;
            }

            try
            {
                _strategy.Decide(_snapshot!, _fish, _work);
            }
            catch (Exception e)
            {
                _error = e;
            }

            _done.Release();
        }
    }
}
