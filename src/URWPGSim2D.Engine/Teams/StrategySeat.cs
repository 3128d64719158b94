namespace URWPGSim2D.Engine.Teams;

/// <summary>The seat of a strategy that runs in the calling program (<see cref="StrategyTeams"/>).</summary>
public sealed class StrategySeat : TeamSeat
{
    /// <summary>Seats <paramref name="strategy"/> for <paramref name="fish"/> of <paramref name="team"/>.</summary>
    /// <param name="spec">How the strategy is shown ("chase-ball", a team's name).</param>
    /// <param name="strategy">The strategy.</param>
    /// <param name="team">The team.</param>
    /// <param name="fish">Indices of the fish it decides for.</param>
    public StrategySeat(string spec, IStrategy strategy, int team, int[] fish)
        : base(spec, team, fish)
    {
        ArgumentNullException.ThrowIfNull(strategy);
        Strategy = strategy;
    }

    /// <summary>The strategy.</summary>
    public IStrategy Strategy { get; }
}
