using System;
using System.Threading;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// A deterministic deadline clock for tests: no real time counts, only what the strategy under test
/// charges with <see cref="Spend"/>; <see cref="Hang"/> charges forever and blocks the strategy's thread
/// until <see cref="Release"/>. Results then never depend on how busy the machine is.
/// </summary>
internal sealed class ManualStrategyClock : StrategyClock
{
    private readonly ManualResetEventSlim _overrun = new(false);
    private readonly ManualResetEventSlim _released = new(false);
    private long _usedTicks;
    private long _budgetTicks = long.MaxValue;
    private volatile bool _hung;

    /// <summary>Charges time to the current call (call it from the strategy).</summary>
    /// <param name="time">Time the strategy "used".</param>
    public void Spend(TimeSpan time)
    {
        long used = Interlocked.Add(ref _usedTicks, time.Ticks);
        if (used > Volatile.Read(ref _budgetTicks))
        {
            _overrun.Set();
        }
    }

    /// <summary>Makes the current call use unbounded time: blocks the strategy's thread until <see cref="Release"/>.</summary>
    public void Hang()
    {
        _hung = true;
        Interlocked.Exchange(ref _usedTicks, long.MaxValue / 2);
        _overrun.Set();
        _released.Wait();
    }

    /// <summary>Lets hung calls return (at the end of a test).</summary>
    public void Release() => _released.Set();

    /// <inheritdoc/>
    public override void Arm(TimeSpan budget)
    {
        Volatile.Write(ref _budgetTicks, budget.Ticks);
        Interlocked.Exchange(ref _usedTicks, 0);
        _hung = false;
        _overrun.Reset();
    }

    /// <summary>A hung call is still busy; any other late call has all its time spent and returns: wait for it.</summary>
    /// <param name="done">Released once when the abandoned call returns.</param>
    public override bool AbandonedCallReturned(SemaphoreSlim done)
    {
        if (_hung && !_released.IsSet)
        {
            return done.Wait(0);
        }

        done.Wait();
        return true;
    }

    /// <inheritdoc/>
    public override void CallStarting()
    {
    }

    /// <inheritdoc/>
    public override TimeSpan CallEnded() => TimeSpan.FromTicks(Interlocked.Read(ref _usedTicks));

    /// <inheritdoc/>
    public override bool WaitForCall(SemaphoreSlim done, TimeSpan budget)
    {
        int which = WaitHandle.WaitAny([done.AvailableWaitHandle, _overrun.WaitHandle]);
        return which == 0 && done.Wait(0);
    }
}
