namespace URWPGSim2D.Strategies;

/// <summary>
/// A team's brain, the shape URWPGSim2D teams know: a team name and, every cycle, one
/// <see cref="Decision"/> per controlled fish, computed from a read-only snapshot of the last cycle.
/// Implementations must have a public parameterless constructor to be loaded from an assembly
/// (<c>--strategy 0=path/MyStrategy.dll</c>).
/// </summary>
public interface IStrategy
{
    /// <summary>The team's display name.</summary>
    string TeamName { get; }

    /// <summary>
    /// Decides the next cycle for the controlled fish. <paramref name="decisions"/> arrives filled
    /// with the last decisions; write the new ones (codes are clamped to 0..15 afterwards).
    /// </summary>
    /// <param name="snapshot">The world at the end of the last cycle, as the team sees it (with observation noise when on).</param>
    /// <param name="fish">Indices into <see cref="MatchSnapshot.Fish"/> of the fish this strategy controls.</param>
    /// <param name="decisions">One decision per entry of <paramref name="fish"/>.</param>
    void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions);
}
