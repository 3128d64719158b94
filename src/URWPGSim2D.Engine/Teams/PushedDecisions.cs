namespace URWPGSim2D.Engine.Teams;

/// <summary>
/// A team whose decisions the calling program pushes before each cycle instead of computing them
/// from the snapshot: write the decisions of the team's fish into <see cref="Pending"/> (in the order
/// of the fish's indices, as <see cref="Matches.SeatPlan"/> gives them to a team's own strategy),
/// then call <see cref="Matches.Match.Step"/>. Give it to <see cref="Matches.MatchSetup.Create"/> like
/// any strategy. The match it plays is the match of a strategy that would have returned the same
/// decisions. A cycle in which nothing was pushed repeats the decisions in force (every fish starts
/// stopped). What a learning environment needs: the agent's actions are the team's decisions.
/// </summary>
public sealed class PushedDecisions : IStrategy, IRestartable
{
    private readonly Decision[] _pending;

    /// <summary>Creates the team of <paramref name="fishCount"/> fish, every one stopped.</summary>
    /// <param name="fishCount">Fish of the team (1 or more).</param>
    /// <param name="teamName">How the team is shown ("pushed" when not given).</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="fishCount"/> is below 1.</exception>
    public PushedDecisions(int fishCount, string teamName = "pushed")
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(fishCount, 1);
        ArgumentNullException.ThrowIfNull(teamName);
        _pending = new Decision[fishCount];
        Array.Fill(_pending, Decision.Stop);
        TeamName = teamName;
    }

    /// <inheritdoc/>
    public string TeamName { get; }

    /// <summary>The decisions of the next cycle, one per fish of the team, in the order of their indices.</summary>
    public Span<Decision> Pending => _pending;

    /// <inheritdoc/>
    /// <exception cref="StrategyContractException">The match seats this team with another number of fish than it was made for.</exception>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (fish.Length != _pending.Length || decisions.Length != _pending.Length)
        {
            throw new StrategyContractException("the team was made for " + _pending.Length + " fish, the match seats it with " + fish.Length);
        }

        _pending.AsSpan().CopyTo(decisions);
    }

    /// <inheritdoc/>
    void IRestartable.Restart() => Array.Fill(_pending, Decision.Stop);
}
