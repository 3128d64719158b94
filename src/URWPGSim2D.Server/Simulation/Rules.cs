using System.Collections.Generic;
using System.Numerics;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// The match rules after each cycle's motion: a ball wholly inside a goal mouth is a goal. Team 0
/// attacks the right goal (+X) and team 1 the left goal (−X), so a ball in the right goal scores
/// for team 0 and a ball in the left goal for team 1. The goal is recorded and the ball is put back
/// at its start position at rest.
/// </summary>
internal static class Rules
{
    /// <summary>The team that scores when a ball ends in the goal on <paramref name="side"/> (−1 left, +1 right).</summary>
    public static int ScoringTeam(int side) => side > 0 ? 0 : 1;

    /// <summary>Scores goals and resets their balls; returns how many balls were reset.</summary>
    public static int Apply(World world, List<GoalEvent> goals)
    {
        int reset = 0;
        foreach (var b in world.Balls)
        {
            Circle c = b.Shape;
            if (!world.Field.IsInGoal(c, out int side))
            {
                continue;
            }

            int team = ScoringTeam(side);
            world.Goals[team]++;
            goals.Add(new GoalEvent(world.Cycle, b.Index, team));
            b.Position = b.StartPosition;
            b.Velocity = Vector2.Zero;
            reset++;
        }

        return reset;
    }
}
