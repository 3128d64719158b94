using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Builds a ready-to-play <see cref="Match"/> from a scenario: the field, fish (deployed sizes),
/// balls, obstacles (indices as in the file; goal blocks follow the obstacles as static bodies) and
/// the strategy slots: a team strategy takes all of that team's fish, otherwise each fish runs the
/// built-in strategy its scenario entry names.
/// </summary>
public static class MatchBuilder
{
    /// <summary>Default time limit of an isolated strategy per cycle, ms.</summary>
    public const int DefaultStrategyTimeoutMs = 100;

    /// <summary>Builds the match.</summary>
    /// <param name="scenario">The scenario.</param>
    /// <param name="teamStrategies">Per team (index 0, 1): a strategy that replaces the scenario's, or null.</param>
    /// <param name="seed">Seed override, or null for the scenario's.</param>
    /// <param name="noise">Noise override, or null for the scenario's.</param>
    /// <param name="strategyTimeoutMs">Time limit of isolated strategies, ms.</param>
    /// <param name="broadPhase">The motion world's broad phase (every kind gives the same match).</param>
    /// <param name="cycles">Cycles the match will last (an item's halves depend on it), or null for the scenario's.</param>
    /// <remarks>
    /// The Box2D side-by-side harness (<c>benchmarks/box2d.sh</c>) finds this method by name and
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
    /// <param name="broadPhase">The motion world's broad phase (every kind gives the same match).</param>
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
        TeamStrategy? Team(int t) => t < teams.Length ? teams[t] : null;
        var slots = new List<StrategySlot>();
        foreach (var plan in SeatPlan.Of(scenario, referee, t => Team(t) switch { null => TeamChoice.Scenario, { Demo: true } => TeamChoice.Demo, _ => TeamChoice.Own }))
        {
            if (plan.Strategy is { } builtIn)
            {
                slots.Add(new StrategySlot(plan.Spec!, builtIn, plan.Team, plan.Fish, isolated: false));
                continue;
            }

            var team = Team(plan.Team)!;
            slots.Add(team switch
            {
                { Remote: { } seat } => new StrategySlot(team.Label, seat.Open(match.Assignment(plan.Team, plan.Fish)), plan.Team, plan.Fish),
                { Host: { } prepared } => new StrategySlot(team.Label, HostedStrategy.Start(prepared, team.Settings ?? HostSettings.Default, match.Assignment(plan.Team, plan.Fish), match.Cycles), plan.Team, plan.Fish),
                { NotCreated: { } why } => StrategySlot.NotCreated(team.Label, why, plan.Team, plan.Fish),
                _ => new StrategySlot(team.Label, team.Strategy!, plan.Team, plan.Fish, team.Isolated, team.Clock),
            });
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
}
