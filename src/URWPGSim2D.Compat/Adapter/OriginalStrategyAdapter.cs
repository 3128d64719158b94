using URWPGSim2D.Strategies;

namespace URWPGSim2D.Compat.Adapter;

/// <summary>
/// Runs a strategy written against the original API (<see cref="StrategyLoader.IStrategy"/>) as an SDK
/// <see cref="IStrategy"/>: every call builds that team's own deep copy of the mission from the snapshot,
/// calls <c>GetDecision(mission, teamId)</c> with the team's index in <c>TeamsRef</c> (which follows the
/// half-time swap) and maps the answer back to the team's fish in order. Fewer decisions than fish (or
/// null) throw <see cref="StrategyContractException"/>; extra ones are ignored.
/// </summary>
public sealed class OriginalStrategyAdapter : IStrategy
{
    private readonly StrategyLoader.IStrategy _strategy;
    private readonly MissionBuilder _builder = new();
    private string? _name;

    /// <summary>Wraps a strategy of the original API.</summary>
    /// <param name="strategy">The team's strategy instance (one per match).</param>
    public OriginalStrategyAdapter(StrategyLoader.IStrategy strategy)
    {
        ArgumentNullException.ThrowIfNull(strategy);
        _strategy = strategy;
    }

    /// <summary>The wrapped strategy.</summary>
    public StrategyLoader.IStrategy Strategy => _strategy;

    /// <summary>The team name the strategy reports (asked once, on first use).</summary>
    public string TeamName => _name ??= _strategy.GetTeamName() ?? string.Empty;

    /// <summary>The mission built for the last call (for tests and diagnostics).</summary>
    internal Common.Mission? LastMission { get; private set; }

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        ArgumentNullException.ThrowIfNull(snapshot);
        if (fish.IsEmpty)
        {
            return;
        }

        int team = snapshot.Fish[fish[0]].Team;
        if (team < _builder.TeamNames.Length)
        {
            _builder.TeamNames[team] = TeamName;
        }

        var mission = _builder.Build(snapshot);
        LastMission = mission;
        int teamId = MissionBuilder.MissionTeam(snapshot, team);
        Common.Decision[]? answer = _strategy.GetDecision(mission, teamId);
        int members = 0;
        foreach (ref readonly var f in snapshot.Fish)
        {
            members += f.Team == team ? 1 : 0;
        }

        if (answer is null || answer.Length < members)
        {
            throw new StrategyContractException(
                $"GetDecision returned {(answer is null ? "null" : answer.Length.ToString(System.Globalization.CultureInfo.InvariantCulture))} decisions for {members} fish");
        }

        for (int k = 0; k < fish.Length; k++)
        {
            int ordinal = 0;
            for (int i = 0; i < fish[k]; i++)
            {
                ordinal += snapshot.Fish[i].Team == team ? 1 : 0;
            }

            decisions[k] = new Decision(answer[ordinal].VCode, answer[ordinal].TCode);
        }
    }
}
