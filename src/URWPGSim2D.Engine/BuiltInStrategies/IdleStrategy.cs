using URWPGSim2D.Engine.Teams;

namespace URWPGSim2D.Engine.BuiltInStrategies;

/// <summary>Built-in <c>idle</c>: every fish stands still (VCode 0, TCode 7).</summary>
public sealed class IdleStrategy : IStrategy, IRestartable
{
    /// <inheritdoc/>
    public string TeamName => "idle";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions) => decisions.Fill(Decision.Stop);

    /// <inheritdoc/>
    void IRestartable.Restart()
    {
    }
}
