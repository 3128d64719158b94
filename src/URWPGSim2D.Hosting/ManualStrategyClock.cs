namespace URWPGSim2D.Hosting;

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
        Interlocked.Exchange(ref _usedTicks, long.MaxValue / 2);
        _overrun.Set();
        _released.Wait();
    }

    /// <summary>Lets hung calls return (at the end of a test).</summary>
    public void Release() => _released.Set();

    /// <inheritdoc/>
    public override void Arm(TimeSpan cpuLimit)
    {
        Volatile.Write(ref _budgetTicks, cpuLimit == Timeout.InfiniteTimeSpan ? long.MaxValue : cpuLimit.Ticks);
        Interlocked.Exchange(ref _usedTicks, 0);
        _overrun.Reset();
    }

    /// <summary>A hung call not yet released is still busy; a released one returns: wait for it.</summary>
    /// <param name="done">Released once when the abandoned call returns.</param>
    public override bool AbandonedCallReturned(SemaphoreSlim done)
    {
        if (!_released.IsSet)
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
    public override (TimeSpan Cpu, TimeSpan Wall) CallEnded()
    {
        var used = TimeSpan.FromTicks(Interlocked.Read(ref _usedTicks));
        return (used, used); // no real time counts: the wall time is the time charged too
    }

    /// <inheritdoc/>
    public override bool WaitForCall(SemaphoreSlim done, TimeSpan cpuLimit, TimeSpan wallLimit)
    {
        int which = WaitHandle.WaitAny([done.AvailableWaitHandle, _overrun.WaitHandle]);
        return which == 0 && done.Wait(0);
    }
}
