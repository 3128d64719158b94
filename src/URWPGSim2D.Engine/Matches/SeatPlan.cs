using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Items;

namespace URWPGSim2D.Engine.Matches;

/// <summary>
/// Who decides for which fish of a scenario, in the order they are asked: a team given its own
/// strategy takes all of its fish (one seat); a team asked to play its item's demo gets the demo
/// strategy for all of its fish; otherwise each fish plays the built-in strategy its scenario entry
/// names (<c>idle</c>, <c>chase-ball</c>, <c>fixed</c>), and the team's fish marked <c>demo</c>
/// share one demo strategy. Seats come in the order of their first fish.
/// </summary>
/// <param name="Spec">How the seat's strategy is shown: the built-in's name, "ITEM demo", or null for a team's own strategy (its builder names it).</param>
/// <param name="Team">The team.</param>
/// <param name="Fish">Indices of the fish the seat decides for.</param>
/// <param name="Strategy">The built-in or demo strategy, or null where the team plays its own.</param>
public sealed record SeatPlan(string? Spec, int Team, int[] Fish, IStrategy? Strategy)
{
    /// <summary>The seats of <paramref name="scenario"/>.</summary>
    /// <param name="scenario">The scenario.</param>
    /// <param name="referee">The match's referee (the demo strategies need it), or null for a scene without an item.</param>
    /// <param name="choice">What each team plays.</param>
    /// <exception cref="ArgumentException">A demo is asked for without an item, or a fish names an unknown built-in strategy.</exception>
    public static IReadOnlyList<SeatPlan> Of(ScenarioDefinition scenario, ItemReferee? referee, Func<int, TeamChoice> choice)
    {
        ArgumentNullException.ThrowIfNull(scenario);
        ArgumentNullException.ThrowIfNull(choice);
        var seats = new List<SeatPlan>();
        int teamCount = 2;
        foreach (var f in scenario.Fish)
        {
            teamCount = Math.Max(teamCount, f.Team + 1);
        }

        var teamDone = new bool[teamCount];
        var demoDone = new bool[teamCount];
        for (int i = 0; i < scenario.Fish.Count; i++)
        {
            var d = scenario.Fish[i];
            var chosen = choice(d.Team);
            if ((chosen == TeamChoice.Scenario && d.Strategy == "demo") || chosen == TeamChoice.Demo)
            {
                // The item's demo strategy takes every demo fish of the team.
                if (referee is null)
                {
                    throw new ArgumentException("the demo strategy needs a competition item", nameof(scenario));
                }

                if (!demoDone[d.Team])
                {
                    demoDone[d.Team] = true;
                    seats.Add(new SeatPlan(referee.Item.Slug + " demo", d.Team, Members(scenario, d.Team, chosen == TeamChoice.Scenario ? "demo" : null), referee.Item.CreateDemoStrategy(d.Team, referee)));
                }
            }
            else if (chosen == TeamChoice.Scenario)
            {
                seats.Add(new SeatPlan(d.Strategy, d.Team, [i], BuiltIn(d)));
            }
            else if (!teamDone[d.Team])
            {
                teamDone[d.Team] = true;
                seats.Add(new SeatPlan(null, d.Team, Members(scenario, d.Team, null), null));
            }
        }

        return seats;
    }

    // The fish of a team (those on the given built-in strategy, or all when null), by index.
    private static int[] Members(ScenarioDefinition scenario, int team, string? strategy)
    {
        var members = new List<int>();
        for (int j = 0; j < scenario.Fish.Count; j++)
        {
            if (scenario.Fish[j].Team == team && (strategy is null || scenario.Fish[j].Strategy == strategy))
            {
                members.Add(j);
            }
        }

        return members.ToArray();
    }

    private static IStrategy BuiltIn(FishDefinition d) => d.Strategy switch
    {
        "idle" => new IdleStrategy(),
        "chase-ball" => new ChaseBallStrategy(),
        "fixed" => new FixedDecisionStrategy(d.Decision),
        _ => throw new ArgumentException($"unknown built-in strategy \"{d.Strategy}\"", nameof(d)),
    };
}
