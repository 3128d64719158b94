using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>Builds item matches for tests.</summary>
internal static class ItemMatches
{
    /// <summary>A match of an item scenario file's JSON (noise off unless the JSON says otherwise).</summary>
    public static Match FromJson(string json, int? cycles = null)
    {
        var scenario = ScenarioFile.Parse(json);
        bool noise = json.Contains("\"noise\"", System.StringComparison.Ordinal) && scenario.Noise;
        return MatchBuilder.Build(scenario, noise: noise, cycles: cycles);
    }

    /// <summary>The item's own layout with its demo strategies, noise on, seed <paramref name="seed"/>.</summary>
    public static Match Item(string slug, ulong seed, int? cycles = null)
    {
        var item = ItemRegistry.Find(slug)!;
        return MatchBuilder.Build(item.CreateScenario(seed), seed: seed, cycles: cycles);
    }

    /// <summary>Every item's slug, in listing order (theory data).</summary>
    public static TheoryData<string> Slugs()
    {
        var data = new TheoryData<string>();
        foreach (var item in ItemRegistry.All)
        {
            data.Add(item.Slug);
        }

        return data;
    }

    /// <summary>Plays until the item ends or <paramref name="cycles"/> cycles are played.</summary>
    public static void PlayOut(this Match match, int cycles)
    {
        for (int k = 0; k < cycles && !match.IsOver; k++)
        {
            match.Step();
        }
    }

    /// <summary>The referee.</summary>
    public static ItemReferee Referee(this Match match) => match.Referee!;
}
