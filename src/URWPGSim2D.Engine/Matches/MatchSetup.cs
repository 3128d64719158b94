using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Teams;

namespace URWPGSim2D.Engine.Matches;

/// <summary>
/// What a match is built from, apart from who decides for its fish: the world of a scenario with
/// its bodies, and the rules it is judged by. A match is then
/// <c>new Match(BuildWorld(scenario), teams, noise, seed, CreateReferee(scenario, cycles, seed))</c>.
/// </summary>
public static class MatchSetup
{
    /// <summary>
    /// A match of <paramref name="scenario"/> whose strategies run in the calling program
    /// (<see cref="StrategyTeams"/>): each team given a strategy plays it with all of its fish, the
    /// others play what the scenario names (built-in strategies, the item's demo), as <see cref="SeatPlan.Of"/> says.
    /// </summary>
    /// <param name="scenario">The scenario (an item's: <c>item.CreateScenario(seed)</c>).</param>
    /// <param name="teams">Per team, its strategy, or null (or a list too short) for the scenario's.</param>
    /// <param name="seed">Seed override, or null for the scenario's.</param>
    /// <param name="noise">Noise override, or null for the scenario's.</param>
    /// <param name="cycles">Cycles the match will last (an item's halves depend on it), or null for the scenario's.</param>
    /// <param name="broadPhase">The motion world's broad phase (every kind gives the same match).</param>
    public static Match Create(ScenarioDefinition scenario, IReadOnlyList<IStrategy?>? teams = null, ulong? seed = null, bool? noise = null, int? cycles = null, BroadPhaseKind broadPhase = BroadPhaseKind.UniformGrid)
    {
        ArgumentNullException.ThrowIfNull(scenario);
        IStrategy? Team(int t) => teams is not null && t < teams.Count ? teams[t] : null;
        var world = BuildWorld(scenario, broadPhase);
        var referee = CreateReferee(scenario, cycles ?? scenario.Cycles, seed ?? scenario.Seed);
        var seats = new List<StrategySeat>();
        foreach (var plan in SeatPlan.Of(scenario, referee, t => Team(t) is null ? TeamChoice.Scenario : TeamChoice.Own))
        {
            var strategy = plan.Strategy ?? Team(plan.Team)!;
            seats.Add(new StrategySeat(plan.Spec ?? strategy.TeamName, strategy, plan.Team, plan.Fish));
        }

        return new Match(world, new StrategyTeams(seats), noise ?? scenario.Noise, seed ?? scenario.Seed, referee);
    }

    /// <summary>
    /// The world of <paramref name="scenario"/>: the field, the fish (deployed sizes), the balls,
    /// the obstacles (indices as in the scenario) and the goal blocks (static bodies after the
    /// obstacles), in a motion world of its own.
    /// </summary>
    /// <param name="scenario">The scenario.</param>
    /// <param name="broadPhase">The motion world's broad phase (every kind gives the same match).</param>
    public static World BuildWorld(ScenarioDefinition scenario, BroadPhaseKind broadPhase = BroadPhaseKind.UniformGrid)
    {
        ArgumentNullException.ThrowIfNull(scenario);
        var field = new Field(scenario.FieldLength, scenario.FieldWidth, scenario.GoalBlocks);
        var motion = new MotionWorld(broadPhase);
        var fish = new FishState[scenario.Fish.Count];
        for (int i = 0; i < fish.Length; i++)
        {
            var d = scenario.Fish[i];
            fish[i] = new FishState(motion, i, d.Team, FishSize.Default, d.Position, d.Heading) { TailPhase = d.TailPhase };
        }

        var balls = new BallState[scenario.Balls.Count];
        for (int i = 0; i < balls.Length; i++)
        {
            var d = scenario.Balls[i];
            balls[i] = new BallState(motion, i, d.Radius, d.Position, d.Velocity);
        }

        var views = new ObstacleView[scenario.Obstacles.Count];
        var statics = new StaticBody[scenario.Obstacles.Count + field.GoalBlocks.Length];
        for (int i = 0; i < views.Length; i++)
        {
            var o = scenario.Obstacles[i];
            views[i] = new ObstacleView(i, o.Kind, o.Center, o.Length, o.Width, o.Heading, o.Radius);
            statics[i] = o.Kind == ObstacleKind.Round
                ? StaticBody.Round(i, o.Center, o.Radius)
                : StaticBody.Rectangle(i, o.Center, o.Length, o.Width, o.Heading);
        }

        for (int g = 0; g < field.GoalBlocks.Length; g++)
        {
            statics[views.Length + g] = StaticBody.GoalBlock(g, field.GoalBlocks[g]);
        }

        return new World(motion, field, fish, balls, views, statics);
    }

    /// <summary>The referee of the scenario's competition item for a match of <paramref name="cycles"/> cycles, or null for a scene without an item (the match then plays by the plain scene's goal rule).</summary>
    /// <param name="scenario">The scenario.</param>
    /// <param name="cycles">Cycles the match will last (an item's halves depend on it).</param>
    /// <param name="seed">The match's seed (an item's random placements).</param>
    /// <exception cref="ArgumentException">The scenario names an item that is not one of this engine's competition items.</exception>
    public static ItemReferee? CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed)
    {
        ArgumentNullException.ThrowIfNull(scenario);
        return scenario.Item switch
        {
            null => null,
            CompetitionItem item => item.CreateReferee(scenario, cycles, seed),
            var other => throw new ArgumentException($"the scenario's item {other.Slug} is not a competition item of this engine", nameof(scenario)),
        };
    }
}
