namespace URWPGSim2D.Hosting;

/// <summary>
/// A team's time for one match: each call has its deadline of CPU time, and twice the larger of that
/// and its CPU time in wall time, not counting the time it waited for a CPU where the kernel measures
/// that (a call that computes is not charged for a busy machine, one that sleeps or waits is), and a
/// banked reserve pays for whatever a call uses beyond them. The match waits for a late
/// call's answer and takes the overrun from the bank, so how fast the server plays never changes
/// which answers count; only a spent bank, or a call longer than <see cref="CallLimit"/> in wall
/// time, makes the team play idle for the rest of the match. The first call (the strategy's code is
/// compiled then) is allowed the hang limit, <see cref="ThreadTimeClock.HangLimitFor"/>, before
/// it draws on the bank.
/// </summary>
public sealed class TimeBank
{
    private bool _first = true;

    /// <summary>A bank of <paramref name="reserve"/> for calls of <paramref name="deadline"/> each.</summary>
    /// <param name="deadline">CPU time a call may use without drawing on the bank.</param>
    /// <param name="reserve">The bank at the start of the match.</param>
    public TimeBank(TimeSpan deadline, TimeSpan reserve)
    {
        if (deadline <= TimeSpan.Zero)
        {
            throw new ArgumentException($"deadline: must be positive, got {deadline.TotalMilliseconds} ms", nameof(deadline));
        }

        if (reserve < TimeSpan.Zero)
        {
            throw new ArgumentException($"reserve: must not be negative, got {reserve.TotalSeconds} s", nameof(reserve));
        }

        Deadline = deadline;
        Reserve = reserve;
        Remaining = reserve;
        CallLimit = CallLimitFor(deadline);
    }

    /// <summary>CPU time a call may use without drawing on the bank.</summary>
    public TimeSpan Deadline { get; }

    /// <summary>The bank at the start of the match.</summary>
    public TimeSpan Reserve { get; }

    /// <summary>What is left of the bank (never below zero).</summary>
    public TimeSpan Remaining { get; private set; }

    /// <summary>What the team has drawn from its bank.</summary>
    public TimeSpan Used => Reserve - Remaining;

    /// <summary>Wall time after which a call is given up whatever the bank holds: <see cref="CallLimitFor"/>.</summary>
    public TimeSpan CallLimit { get; }

    /// <summary>Calls that drew on the bank.</summary>
    public int LateCalls { get; private set; }

    /// <summary>The longest call so far: the larger of its CPU and wall time.</summary>
    public TimeSpan Slowest { get; private set; }

    /// <summary>Whether the bank is spent (the team plays idle from then on).</summary>
    public bool Spent { get; private set; }

    /// <summary>The default bank of a match: a tenth of all its calls' deadlines, at least 5 s.</summary>
    /// <param name="cycles">Cycles of the match.</param>
    /// <param name="deadlineMs">The deadline of one call, ms.</param>
    public static TimeSpan DefaultFor(int cycles, int deadlineMs) =>
        TimeSpan.FromMilliseconds(Math.Max(5_000.0, (double)Math.Max(cycles, 0) * deadlineMs / 10));

    /// <summary>The wall time after which a call is given up however much bank is left: a hundred deadlines, at least 10 s (a host's own time: <see cref="HostWatchdog.Overdue"/>).</summary>
    /// <param name="deadline">The deadline of one call.</param>
    public static TimeSpan CallLimitFor(TimeSpan deadline) => TimeSpan.FromTicks(Math.Max(TimeSpan.TicksPerSecond * 10, deadline.Ticks * 100));

    /// <summary>CPU time the next call may use before it draws on the bank.</summary>
    public TimeSpan CpuAllowance => _first ? ThreadTimeClock.HangLimitFor(Deadline) : Deadline;

    /// <summary>Wall time the next call may take before it draws on the bank when it uses no more CPU time than its allowance: twice that.</summary>
    public TimeSpan WallAllowance => CpuAllowance * 2;

    /// <summary>
    /// How long to wait for the next call's answer in wall time: as long as it could take without
    /// spending the bank (using its CPU allowance and the whole bank in CPU time, twice that in wall
    /// time, and the bank again), at most <see cref="CallLimit"/>.
    /// </summary>
    public TimeSpan WaitLimit => Min(WaitOnBank, WaitCap);

    /// <summary>Whether the next wait (<see cref="WaitLimit"/>) ends at the call limit rather than where the bank would be spent.</summary>
    public bool WaitEndsAtCallLimit => WaitOnBank > WaitCap;

    // As long as the next call could take without spending the bank, and the most any call is waited for.
    private TimeSpan WaitOnBank => (CpuLimit * 2) + Remaining;

    private TimeSpan WaitCap => Max(CallLimit, WallAllowance);

    /// <summary>How much CPU time the next call may use before the bank is spent.</summary>
    public TimeSpan CpuLimit => CpuAllowance + Remaining;

    /// <summary>
    /// Takes a finished call's overrun from the bank: the larger of its CPU time beyond
    /// <see cref="CpuAllowance"/> and its wall time beyond twice the larger of that allowance and its
    /// CPU time. False when that spends the bank: the call's answer does not count and the team plays idle.
    /// </summary>
    /// <param name="cpu">CPU time of the call (all the strategy's threads and processes where that is measured), or null where only wall time is known.</param>
    /// <param name="wall">Wall time from the question to the answer.</param>
    /// <param name="waiting">Of that wall time, how long the strategy was ready to run but waited for a CPU (a busy machine's doing, not the strategy's), or null where it is not measured.</param>
    public bool Charge(TimeSpan? cpu, TimeSpan wall, TimeSpan? waiting = null)
    {
        TimeSpan computing = cpu is { } c ? c : TimeSpan.Zero;
        TimeSpan own = waiting is { } w && w > TimeSpan.Zero ? Max(wall - w, TimeSpan.Zero) : wall;
        TimeSpan overrun = Max(computing - CpuAllowance, own - (Max(CpuAllowance, computing) * 2));
        _first = false;
        Slowest = Max(Slowest, Max(cpu ?? TimeSpan.Zero, wall));
        if (overrun <= TimeSpan.Zero)
        {
            return true;
        }

        LateCalls++;
        if (overrun > Remaining)
        {
            Remaining = TimeSpan.Zero;
            Spent = true;
            return false;
        }

        Remaining -= overrun;
        return true;
    }

    /// <summary>Records a call given up on after <paramref name="waited"/> (no answer in time): the bank is spent.</summary>
    /// <param name="waited">Wall time waited.</param>
    public void GiveUp(TimeSpan waited)
    {
        _first = false;
        LateCalls++;
        Slowest = Max(Slowest, waited);
        Remaining = TimeSpan.Zero;
        Spent = true;
    }

    private static TimeSpan Max(TimeSpan a, TimeSpan b) => a > b ? a : b;

    private static TimeSpan Min(TimeSpan a, TimeSpan b) => a < b ? a : b;
}
