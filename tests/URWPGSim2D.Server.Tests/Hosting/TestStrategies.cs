namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>Swims straight at full speed until cycle <see cref="FailFrom"/>, then throws every cycle.</summary>
internal sealed class ThrowingStrategy : IStrategy
{
    public int FailFrom { get; init; } = 5;

    public string TeamName => "throwing";

    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (snapshot.Cycle >= FailFrom)
        {
            decisions.Fill(new Decision(1, 1));
            throw new InvalidOperationException("strategy bug");
        }

        decisions.Fill(new Decision(15, 7));
    }
}

/// <summary>
/// Answers V9 T9 at once, except at cycle 3 where it uses <see cref="Spend"/> of its clock's time
/// (400 ms by default, far past a 50 ms deadline) and answers V1 T1.
/// </summary>
internal sealed class SlowStrategy(ManualStrategyClock clock) : IStrategy
{
    public TimeSpan Spend { get; init; } = TimeSpan.FromMilliseconds(400);

    public string TeamName => "slow";

    /// <summary>Calls made so far.</summary>
    public int Calls { get; private set; }

    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        Calls++;
        if (snapshot.Cycle == 3)
        {
            clock.Spend(Spend);
            decisions.Fill(new Decision(1, 1));
            return;
        }

        decisions.Fill(new Decision(9, 9));
    }
}

/// <summary>Answers V9 T9 until cycle 2, then never returns (until its clock is released).</summary>
internal sealed class HangingStrategy(ManualStrategyClock clock) : IStrategy
{
    public string TeamName => "hang";

    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (snapshot.Cycle == 2)
        {
            clock.Hang();
        }

        decisions.Fill(new Decision(9, 9));
    }
}
