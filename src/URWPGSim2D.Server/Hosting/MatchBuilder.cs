using System;
using System.Collections.Generic;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// Builds a ready-to-play <see cref="Match"/> from a scenario: the field, fish (deployed sizes),
/// balls, obstacles (indices as in the file; goal blocks follow the obstacles as static bodies) and
/// the strategy slots: a team strategy takes all of that team's fish, otherwise each fish runs the
/// built-in strategy its scenario entry names.
/// </summary>
internal static class MatchBuilder
{
    /// <summary>Default time limit of an isolated strategy per cycle, ms.</summary>
    public const int DefaultStrategyTimeoutMs = 100;

    /// <summary>Builds the match.</summary>
    /// <param name="scenario">The scenario.</param>
    /// <param name="teamStrategies">Per team (index 0, 1): a strategy that replaces the scenario's, or null.</param>
    /// <param name="seed">Seed override, or null for the scenario's.</param>
    /// <param name="noise">Noise override, or null for the scenario's.</param>
    /// <param name="strategyTimeoutMs">Time limit of isolated strategies, ms.</param>
    /// <param name="broadPhase">The stepper's broad phase (every kind gives the same match).</param>
    /// <param name="cycles">Cycles the match will last (an item's halves depend on it), or null for the scenario's.</param>
    /// <remarks>
    /// The Box2D side-by-side harness (<c>../shared/peers/box2d</c>) finds this method by name and
    /// calls it with these seven arguments: keep it the only <c>Build</c>, with this signature.
    /// </remarks>
    public static Match Build(ScenarioDefinition scenario, TeamStrategy?[]? teamStrategies = null, ulong? seed = null, bool? noise = null, int strategyTimeoutMs = DefaultStrategyTimeoutMs, BroadPhaseKind broadPhase = BroadPhaseKind.UniformGrid, int? cycles = null) =>
        BuildRecording(scenario, teamStrategies, seed, noise, strategyTimeoutMs, broadPhase, cycles, debugDraw: false, strategyLog: false);

    /// <summary>Builds the match, recording what the strategies draw or print when asked.</summary>
    /// <param name="scenario">The scenario.</param>
    /// <param name="teamStrategies">Per team (index 0, 1): a strategy that replaces the scenario's, or null.</param>
    /// <param name="seed">Seed override, or null for the scenario's.</param>
    /// <param name="noise">Noise override, or null for the scenario's.</param>
    /// <param name="strategyTimeoutMs">Time limit of isolated strategies, ms.</param>
    /// <param name="broadPhase">The stepper's broad phase (every kind gives the same match).</param>
    /// <param name="cycles">Cycles the match will last (an item's halves depend on it), or null for the scenario's.</param>
    /// <param name="debugDraw">Whether the strategies' debug drawings are recorded (<c>run --debug-draw</c>).</param>
    /// <param name="strategyLog">Whether what the strategies print is recorded (<c>run --strategy-log</c>).</param>
    /// <param name="timeBank">Each team's time bank for late calls, or null for <see cref="TimeBank.DefaultFor"/>.</param>
    public static Match BuildRecording(ScenarioDefinition scenario, TeamStrategy?[]? teamStrategies = null, ulong? seed = null, bool? noise = null, int strategyTimeoutMs = DefaultStrategyTimeoutMs, BroadPhaseKind broadPhase = BroadPhaseKind.UniformGrid, int? cycles = null, bool debugDraw = false, bool strategyLog = false, TimeSpan? timeBank = null)
    {
        var world = MatchSetup.BuildWorld(scenario, broadPhase);
        var referee = MatchSetup.CreateReferee(scenario, cycles ?? scenario.Cycles, seed ?? scenario.Seed);
        var match = new MatchFacts(world, referee, strategyTimeoutMs, cycles ?? scenario.Cycles, debugDraw, strategyLog);
        var slots = Slots(scenario, teamStrategies ?? new TeamStrategy?[2], referee, match);
        foreach (var slot in slots)
        {
            if (debugDraw)
            {
                slot.RecordDrawings();
            }

            if (strategyLog)
            {
                slot.RecordLog();
            }
        }

        var host = new StrategyCaller(slots, strategyTimeoutMs, timeBank ?? TimeBank.DefaultFor(cycles ?? scenario.Cycles, strategyTimeoutMs));
        return new Match(world, host, noise ?? scenario.Noise, seed ?? scenario.Seed, referee);
    }

    private static StrategySlot[] Slots(ScenarioDefinition scenario, TeamStrategy?[] teams, Engine.Items.ItemReferee? referee, MatchFacts match)
    {
        var slots = new List<StrategySlot>();
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
            TeamStrategy? team = d.Team < teams.Length ? teams[d.Team] : null;
            if ((team is null && d.Strategy == "demo") || team is { Demo: true })
            {
                // The item's demo strategy takes every demo fish of the team.
                if (referee is null)
                {
                    throw new ArgumentException("the demo strategy needs a competition item", nameof(scenario));
                }

                if (!demoDone[d.Team])
                {
                    demoDone[d.Team] = true;
                    slots.Add(new StrategySlot(referee.Item.Slug + " demo", referee.Item.CreateDemoStrategy(d.Team, referee), d.Team, Members(scenario, d.Team, team is null ? "demo" : null), isolated: false));
                }
            }
            else if (team is null)
            {
                slots.Add(new StrategySlot(d.Strategy, BuiltIn(d), d.Team, [i], isolated: false));
            }
            else if (!teamDone[d.Team])
            {
                teamDone[d.Team] = true;
                int[] members = Members(scenario, d.Team, null);
                slots.Add(team switch
                {
                    { Remote: { } seat } => new StrategySlot(team.Label, seat.Open(match.Assignment(d.Team, members)), d.Team, members),
                    { Host: { } prepared } => new StrategySlot(team.Label, HostedStrategy.Start(prepared, team.Settings ?? HostSettings.Default, match.Assignment(d.Team, members), match.Cycles), d.Team, members),
                    { NotCreated: { } why } => StrategySlot.NotCreated(team.Label, why, d.Team, members),
                    _ => new StrategySlot(team.Label, team.Strategy!, d.Team, members, team.Isolated, team.Clock),
                });
            }
        }

        // Every strategy host says hello before the match (they start side by side): their names are
        // then known to the trace, the summary and the result files from the first line on.
        foreach (var slot in slots)
        {
            (slot.Hosted as StrategyConnection)?.Introduce();
        }

        return slots.ToArray();
    }

    // What a strategy host is told of the match (docs/protocol.md, assignment).
    private sealed record MatchFacts(World World, Engine.Items.ItemReferee? Referee, int DeadlineMs, int Cycles, bool DebugDraw, bool StrategyLog)
    {
        public Protocol.AssignmentMessage Assignment(int team, int[] fish) => new(
            Protocol.ProtocolVersion.Current, team, Referee?.Item.Slug ?? "", Referee?.Item.ChineseName ?? "match", fish,
            World.Fish.Length, World.Balls.Length, Referee?.Cycles ?? 0, DeadlineMs, World.Field.Length, World.Field.Width, World.Obstacles)
        {
            Draw = DebugDraw,
            Log = StrategyLog,
        };
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
