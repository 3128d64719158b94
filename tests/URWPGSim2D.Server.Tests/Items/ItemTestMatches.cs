using URWPGSim2D.Engine.Matches;

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

/// <summary>Drives a referee without physics: the test places the bodies, each call is one cycle judged.</summary>
internal static class Judging
{
    /// <summary>Advances the world's clock by one cycle and judges it with <paramref name="contacts"/>.</summary>
    public static void JudgeCycle(this Match match, params ContactRecord[] contacts)
    {
        match.World.Cycle++;
        match.Referee!.Judge(match.World, contacts);
    }

    /// <summary>Judges <paramref name="cycles"/> cycles with the same contacts.</summary>
    public static void JudgeCycles(this Match match, int cycles, params ContactRecord[] contacts)
    {
        for (int k = 0; k < cycles; k++)
        {
            match.JudgeCycle(contacts);
        }
    }

    /// <summary>A fish–ball contact record.</summary>
    public static ContactRecord Touch(int fish, int ball) =>
        new(new CandidatePair(PairKind.FishBall, fish, ball, 1f), 1, -1, System.Numerics.Vector2.Zero, System.Numerics.Vector2.UnitX, System.Numerics.Vector2.Zero, 0.5);
}
