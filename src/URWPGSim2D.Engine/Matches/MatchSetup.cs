using System;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Engine.Matches;

/// <summary>
/// What a match is built from, apart from who decides for its fish: the world of a scenario with
/// its bodies, and the rules it is judged by. A match is then
/// <c>new Match(BuildWorld(scenario), teams, noise, seed, CreateReferee(scenario, cycles, seed))</c>.
/// </summary>
public static class MatchSetup
{
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
        var motion = new Stepper(broadPhase);
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
