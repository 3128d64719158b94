using System;

namespace URWPGSim2D.Server.BuiltInStrategies;

/// <summary>Built-in <c>idle</c>: every fish stands still (VCode 0, TCode 7).</summary>
internal sealed class IdleStrategy : IStrategy
{
    /// <inheritdoc/>
    public string TeamName => "idle";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions) => decisions.Fill(Decision.Stop);
}
