using System.Collections.Generic;
using System.Linq;
using URWPGSim2D.Server.Items;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>Matches of an item for tests: noise off unless asked, the item's layout possibly edited.</summary>
internal static class ItemTestMatches
{
    /// <summary>A match of the item's layout (every fish on <paramref name="strategy"/>) lasting <paramref name="cycles"/>.</summary>
    public static Match Build(CompetitionItem item, int cycles, string strategy = "idle", ulong seed = 1, bool noise = false, System.Func<ScenarioDefinition, ScenarioDefinition>? edit = null)
    {
        var scenario = item.CreateScenario(seed);
        scenario = scenario with { Cycles = cycles, Fish = scenario.Fish.Select(f => f with { Strategy = strategy }).ToList() };
        if (edit is not null)
        {
            scenario = edit(scenario);
        }

        return MatchBuilder.Build(scenario, seed: seed, noise: noise, cycles: cycles);
    }

    /// <summary>Plays until the item's match is over (at most <paramref name="limit"/> cycles); returns the cycles played.</summary>
    public static int PlayAll(this Match match, int limit = 100_000)
    {
        int n = 0;
        while (!match.IsOver && n < limit)
        {
            match.Step();
            n++;
        }

        return n;
    }

    /// <summary>The referee's events of a kind.</summary>
    public static List<ItemEvent> EventsOf(this Match match, string kind) => match.Referee!.Events.Where(e => e.Kind == kind).ToList();
}
