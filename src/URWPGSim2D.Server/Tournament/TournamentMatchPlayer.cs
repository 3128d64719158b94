using System;
using URWPGSim2D.Server.Batch;
using URWPGSim2D.Server.Items;
using URWPGSim2D.Server.Rendering;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Simulation;
using URWPGSim2D.Server.Trace;
using URWPGSim2D.Server.Viewer;

namespace URWPGSim2D.Server.Tournament;

/// <summary>
/// Plays one match of a tournament: the item's layout of the match's seed, the entrants' teams
/// (a demo entrant keeps the item's demo strategy), the seed, the length and the strategies' time
/// limit; optionally records it into a replay page (the viewer's page writer). The tournament's
/// only coupling to the match loop, kept in this one place.
/// </summary>
internal static class TournamentMatchPlayer
{
    /// <summary>Plays the match and returns its result (index and seed as scheduled).</summary>
    /// <param name="item">The item.</param>
    /// <param name="match">The scheduled match.</param>
    /// <param name="teams">Per team, the entrant's strategy, or null for the item's demo strategy.</param>
    /// <param name="cycles">Cycles of the match.</param>
    /// <param name="strategyTimeoutMs">Time limit of loaded strategies per call, ms.</param>
    /// <param name="replayPage">Where to write the replay page, or null for none.</param>
    public static MatchResult Play(CompetitionItem item, ScheduledMatch match, TeamStrategy?[] teams, int cycles, int strategyTimeoutMs, string? replayPage)
    {
        var scenario = item.CreateScenario(match.Seed);
        var played = MatchBuilder.Build(scenario, teams, match.Seed, noise: null, strategyTimeoutMs, cycles: cycles);
        var replay = replayPage is null ? null : new ReplayRecorder();
        var lines = replay is null ? null : new TraceLine(played);
        try
        {
            if (lines is not null)
            {
                replay!.Add(lines.Write(ReadOnlySpan<ContactRecord>.Empty));
            }

            for (int k = 0; k < (played.Referee?.MaxCycles ?? cycles) && !played.IsOver; k++)
            {
                played.Step();
                if (lines is not null)
                {
                    replay!.Add(lines.Write(played.Contacts.Cycle));
                }
            }
        }
        finally
        {
            played.Strategies.Stop();
        }

        if (replay is not null)
        {
            AtomicFile.WriteAllText(replayPage!, ReplayPage.Replay(replay.ToJson()));
        }

        return MatchResult.Of(match.Index, match.Seed, played);
    }
}
