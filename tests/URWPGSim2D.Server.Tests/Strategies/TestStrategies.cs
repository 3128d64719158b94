using System;
using System.Threading;
using URWPGSim2D.Server.Strategies;

namespace URWPGSim2D.Server.Tests.Strategies;

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

/// <summary>Answers V9 T9 at once, except at cycle 3 where it sleeps far past any time limit and answers V1 T1.</summary>
internal sealed class SlowStrategy : IStrategy
{
    public string TeamName => "slow";

    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (snapshot.Cycle == 3)
        {
            Thread.Sleep(400);
            decisions.Fill(new Decision(1, 1));
            return;
        }

        decisions.Fill(new Decision(9, 9));
    }
}
