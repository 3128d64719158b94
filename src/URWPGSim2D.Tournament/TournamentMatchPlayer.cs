using URWPGSim2D.Hosting;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;
using URWPGSim2D.Viewer;

namespace URWPGSim2D.Tournament;

/// <summary>
/// Plays one match of a tournament through the server's one match loop (<see cref="MatchLoop"/>):
/// the item's layout of the match's seed, the entrants' teams (a demo entrant keeps the item's demo
/// strategy), the seed, the length and the strategies' time limit; optionally recorded into a
/// replay page (the viewer's page writer).
/// </summary>
public static class TournamentMatchPlayer
{
    /// <summary>The settings of the match: the item's layout of its seed, the teams, the seed, the length and the time limit.</summary>
    /// <param name="item">The item.</param>
    /// <param name="match">The scheduled match.</param>
    /// <param name="teams">Per team, the entrant's strategy, or null for the item's demo strategy.</param>
    /// <param name="cycles">Cycles of the match.</param>
    /// <param name="strategyTimeoutMs">Time limit of loaded strategies per call, ms.</param>
    public static MatchSettings Settings(CompetitionItem item, ScheduledMatch match, TeamStrategy?[] teams, int cycles, int strategyTimeoutMs) =>
        new(item.CreateScenario(match.Seed), cycles, match.Seed, Noise: null, teams, strategyTimeoutMs);

    /// <summary>
    /// Builds the match and waits for the clients of its remote entrants (<see cref="StrategyCaller.ConnectRemoteTeams"/>):
    /// a client that plays a series is taken at once, another is waited for up to the seat's <c>--remote-wait</c>.
    /// </summary>
    /// <param name="settings">The match's settings.</param>
    /// <exception cref="TeamFaultException">A remote entrant's client did not come: the match is that entrant's forfeit.</exception>
    public static Match Build(MatchSettings settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        var match = settings.Build();
        try
        {
            match.Caller().ConnectRemoteTeams();
        }
        catch (RemoteWaitException e)
        {
            match.Teams.Stop();
            throw new TeamFaultException(e.Team, e);
        }

        return match;
    }

    /// <summary>Plays the match and returns its result (index and seed as scheduled).</summary>
    /// <param name="item">The item.</param>
    /// <param name="match">The scheduled match.</param>
    /// <param name="teams">Per team, the entrant's strategy, or null for the item's demo strategy.</param>
    /// <param name="cycles">Cycles of the match.</param>
    /// <param name="strategyTimeoutMs">Time limit of loaded strategies per call, ms.</param>
    /// <param name="replayPage">Where to write the replay page, or null for none.</param>
    public static MatchResult Play(CompetitionItem item, ScheduledMatch match, TeamStrategy?[] teams, int cycles, int strategyTimeoutMs, string? replayPage) =>
        Play(item, match, teams, cycles, strategyTimeoutMs, replayPage, null);

    /// <summary>Plays the match and returns its result; with <paramref name="output"/>, also keeps what each team's strategy printed and its slowest call there (never in the replay page).</summary>
    /// <param name="item">The item.</param>
    /// <param name="match">The scheduled match.</param>
    /// <param name="teams">Per team, the entrant's strategy, or null for the item's demo strategy.</param>
    /// <param name="cycles">Cycles of the match.</param>
    /// <param name="strategyTimeoutMs">Time limit of loaded strategies per call, ms.</param>
    /// <param name="replayPage">Where to write the replay page, or null for none.</param>
    /// <param name="output">Where each team's printed text and slowest call go, or null.</param>
    public static MatchResult Play(CompetitionItem item, ScheduledMatch match, TeamStrategy?[] teams, int cycles, int strategyTimeoutMs, string? replayPage, StrategyOutput? output)
    {
        var settings = Settings(item, match, teams, cycles, strategyTimeoutMs) with { StrategyLog = output is not null };
        var replay = replayPage is null ? null : new ReplayRecorder();
        Engine.Trace.ITraceSink? sink = output is not null && replay is not null ? new StrategyOutput.WithoutLogs(replay) : replay;
        using var loop = new MatchLoop(Build(settings), settings.Cycles, sink);
        loop.Play(played: output is null ? null : _ => output.AddCycle(loop.Match));
        output?.End(loop.Match);
        if (replay is not null)
        {
            AtomicFile.WriteAllText(replayPage!, ReplayPage.Replay(replay.ToJson()));
        }

        return MatchResult.Of(match.Index, match.Seed, loop.Match);
    }
}
