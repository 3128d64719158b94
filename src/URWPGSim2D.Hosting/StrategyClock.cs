namespace URWPGSim2D.Hosting;

/// <summary>
/// Measures a strategy call. The server's clock (<see cref="ThreadTimeClock"/>) counts the CPU time of
/// the strategy's own thread, so a busy machine neither cuts off a fast strategy nor lets a slow one
/// through, and the call's wall time beside it; tests use a clock whose time only the test strategy
/// advances. One clock serves one strategy thread.
/// </summary>
public abstract class StrategyClock
{
    /// <summary>On the host's thread, before the call is handed to the strategy's thread.</summary>
    /// <param name="cpuLimit">The CPU time after which the call is given up.</param>
    public virtual void Arm(TimeSpan cpuLimit)
    {
    }

    /// <summary>
    /// On the host's thread, at the next call after a call that was given up on: true when that call
    /// has returned by now (its answer is dropped and a new call may start), false while it is still busy.
    /// </summary>
    /// <param name="done">Released once when the abandoned call returns.</param>
    public virtual bool AbandonedCallReturned(SemaphoreSlim done) => done.Wait(0);

    /// <summary>On the strategy's thread, just before the call.</summary>
    public abstract void CallStarting();

    /// <summary>On the strategy's thread, just after the call: the CPU time and the wall time the call used.</summary>
    public abstract (TimeSpan Cpu, TimeSpan Wall) CallEnded();

    /// <summary>
    /// On the host's thread: waits until the call signals <paramref name="done"/> (true), or has used more
    /// than <paramref name="cpuLimit"/> of CPU time or <paramref name="wallLimit"/> of wall time (false;
    /// the call goes on and its answer is discarded). <see cref="Timeout.InfiniteTimeSpan"/> for both waits for as long as the call takes.
    /// </summary>
    /// <param name="done">Released once when the call returns.</param>
    /// <param name="cpuLimit">CPU time after which the call is given up.</param>
    /// <param name="wallLimit">Wall time after which the call is given up.</param>
    public abstract bool WaitForCall(SemaphoreSlim done, TimeSpan cpuLimit, TimeSpan wallLimit);
}
