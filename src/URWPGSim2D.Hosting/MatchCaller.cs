using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Hosting;

/// <summary>The strategy slots of a match built here (<see cref="MatchBuilder"/>): faults, time banks and hosts per strategy.</summary>
public static class MatchCaller
{
    /// <summary>The <see cref="StrategyCaller"/> that decides for <paramref name="match"/>'s fish.</summary>
    /// <param name="match">A match built by <see cref="MatchBuilder"/>.</param>
    /// <exception cref="InvalidOperationException">The match's teams are not strategy slots (a match built elsewhere).</exception>
    public static StrategyCaller Caller(this Match match) =>
        match.Teams as StrategyCaller ?? throw new InvalidOperationException("the match's teams are not strategy slots: it was not built by MatchBuilder");
}
