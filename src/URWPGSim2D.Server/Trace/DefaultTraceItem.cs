using System.Collections.Generic;
using System.Globalization;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Trace;

/// <summary>
/// The trace information of a plain match (no competition item): slug <c>default</c>, no zones,
/// no ball values, the score is the goal count of each team and the events are its goals.
/// </summary>
internal sealed class DefaultTraceItem(Match match) : ITraceItemInfo
{
    private int _nextGoal;

    /// <inheritdoc/>
    public string Slug => "default";

    /// <inheritdoc/>
    public IReadOnlyList<TraceZone> Zones { get; } = [];

    /// <inheritdoc/>
    public double? BallValue(int ball) => null;

    /// <inheritdoc/>
    public double Score(int team) => match.World.Goals[team];

    /// <inheritdoc/>
    public void AddEvents(int cycle, List<TraceEvent> events)
    {
        var goals = match.Goals;
        while (_nextGoal < goals.Count && goals[_nextGoal].Cycle <= cycle)
        {
            var g = goals[_nextGoal++];
            if (g.Cycle == cycle)
            {
                events.Add(GoalEvent(g));
            }
        }
    }

    /// <summary>The trace event of a goal.</summary>
    public static TraceEvent GoalEvent(GoalEvent goal) =>
        new("goal", string.Create(CultureInfo.InvariantCulture, $"team {goal.Team} scores ball {goal.Ball}"), Team: goal.Team, Ball: goal.Ball, Value: 1);
}
