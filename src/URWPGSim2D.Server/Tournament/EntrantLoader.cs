using System;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Hosting;

namespace URWPGSim2D.Server.Tournament;

/// <summary>
/// Makes an entrant's team strategy for a match through the resolver the <c>run</c> command uses
/// (<see cref="StrategyResolver"/>): a fresh instance per match, so no state carries over; the
/// item's demo strategy is no team strategy (null: the item's layout puts its demo on the team).
/// <see cref="Check"/> loads each entrant once before the tournament plays, to list the ones that
/// cannot be loaded with their reason.
/// </summary>
internal static class EntrantLoader
{
    /// <summary>The entrant's team strategy for one match (isolated: its faults are charged to its team), or null for the demo.</summary>
    /// <exception cref="StrategyLoadException">The entrant cannot be loaded.</exception>
    public static TeamStrategy? Create(Entrant entrant) =>
        entrant.Spec == Entrant.Demo ? null : new TeamStrategy(entrant.Name, StrategyResolver.Load(entrant.Spec), Isolated: true);

    /// <summary>The one-line reason of a load failure: the message, and the first compile error when there are some.</summary>
    public static string Reason(StrategyLoadException e) =>
        StandingsText.Line(e.Details.Count == 0 ? e.Message : $"{e.Message.TrimEnd(':', ' ')}; first: {e.Details[0]}");

    /// <summary>Null when the entrant loads, else its one-line reason.</summary>
    public static string? Check(Entrant entrant)
    {
        try
        {
            Create(entrant);
            return null;
        }
        catch (StrategyLoadException e)
        {
            return Reason(e);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return StandingsText.Line($"{e.GetType().Name}: {e.Message}"); // hostile code: whatever it throws, the tournament goes on
        }
    }
}
