using System;
using System.Threading;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// Measures a strategy call against its deadline. The server's clock (<see cref="ThreadTimeClock"/>)
/// counts the CPU time of the strategy's own thread, so a busy machine neither cuts off a fast
/// strategy nor lets a slow one through; tests use a clock whose time only the test strategy advances.
/// One clock serves one strategy thread.
/// </summary>
internal abstract class StrategyClock
{
    /// <summary>On the host's thread, before the call is handed to the strategy's thread.</summary>
    /// <param name="budget">The deadline of the call.</param>
    public virtual void Arm(TimeSpan budget)
    {
    }

    /// <summary>
    /// On the host's thread, at the next call after a call that missed its deadline: true when that call
    /// has returned by now (its answer is dropped and a new call may start), false while it is still busy.
    /// </summary>
    /// <param name="done">Released once when the abandoned call returns.</param>
    public virtual bool AbandonedCallReturned(SemaphoreSlim done) => done.Wait(0);

    /// <summary>On the strategy's thread, just before the call.</summary>
    public abstract void CallStarting();

    /// <summary>On the strategy's thread, just after the call: the time the call used.</summary>
    public abstract TimeSpan CallEnded();

    /// <summary>
    /// On the host's thread: waits until the call signals <paramref name="done"/> (true) or has used more
    /// than <paramref name="budget"/> (false; the call goes on and its answer is discarded).
    /// </summary>
    /// <param name="done">Released once when the call returns.</param>
    /// <param name="budget">The deadline.</param>
    public abstract bool WaitForCall(SemaphoreSlim done, TimeSpan budget);
}
