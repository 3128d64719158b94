using System.Collections.Concurrent;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Scenario;

namespace URWPGSim2D.Hosting;

/// <summary>The keys of an item's mission variables (the original's <c>HtMissionVariables</c>), read from a match of the item once it is ready to play.</summary>
internal static class ItemVariables
{
    private static readonly ConcurrentDictionary<string, IReadOnlyList<string>> Keys = new();

    /// <summary>The keys strategies of <paramref name="item"/> can read, in the order the item sets them.</summary>
    /// <param name="item">The item.</param>
    public static IReadOnlyList<string> Of(CompetitionItem item) => Keys.GetOrAdd(item.Slug, _ =>
    {
        var match = MatchBuilder.Build(item.CreateScenario(1), new TeamStrategy?[System.Math.Max(2, item.TeamCount)], seed: 1, cycles: 2);
        match.Step();
        match.Teams.Stop();
        return [.. match.Rules.Variables.Keys];
    });
}
