using URWPGSim2D.Common;

namespace URWPGSim2D.StrategyLoader;

/// <summary>
/// The original's strategy interface. A team's class is <c>URWPGSim2D.Strategy.Strategy</c> (usually
/// also a <see cref="System.MarshalByRefObject"/>); one instance lives for the whole match.
/// </summary>
public interface IStrategy
{
    /// <summary>The team's name.</summary>
    /// <returns>The name shown in the summary.</returns>
    string GetTeamName();

    /// <summary>Decides the next cycle for every fish of team <paramref name="teamId"/>.</summary>
    /// <param name="mission">This team's own copy of the match (it may be changed freely).</param>
    /// <param name="teamId">The team's index in <see cref="Mission.TeamsRef"/> (0 = the team on the left half).</param>
    /// <returns>One decision per fish of the team, in the order of <c>TeamsRef[teamId].Fishes</c>.</returns>
    Decision[] GetDecision(Mission mission, int teamId);
}
