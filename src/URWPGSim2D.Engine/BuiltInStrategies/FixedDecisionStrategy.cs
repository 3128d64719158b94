namespace URWPGSim2D.Engine.BuiltInStrategies;

/// <summary>Built-in <c>fixed</c>: every fish repeats one decision forever.</summary>
/// <param name="decision">The decision to repeat.</param>
public sealed class FixedDecisionStrategy(Decision decision) : IStrategy
{
    /// <summary>The repeated decision.</summary>
    public Decision Decision { get; } = decision;

    /// <inheritdoc/>
    public string TeamName => $"fixed V{Decision.VCode} T{Decision.TCode}";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions) => decisions.Fill(Decision);
}
