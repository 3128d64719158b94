namespace URWPGSim2D.Engine.Items;

/// <summary>How an item's match ended: the winner (or none) and the rule that decided it.</summary>
/// <param name="Winner">The winning team, or −1 for a draw or an item without a winner.</param>
/// <param name="Rule">The deciding rule in words, e.g. "higher score", "earlier first score", "tie".</param>
public readonly record struct MatchOutcome(int Winner, string Rule)
{
    /// <summary>The higher score wins; <paramref name="tie"/> decides equal scores.</summary>
    public static MatchOutcome ByScore(int score0, int score1, System.Func<MatchOutcome> tie) =>
        score0 > score1 ? new MatchOutcome(0, "higher score")
        : score1 > score0 ? new MatchOutcome(1, "higher score")
        : tie();
}
