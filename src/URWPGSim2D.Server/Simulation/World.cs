using System;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Server.Hosting;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// The pool and everything in it: the field (walls, goal blocks), fish, balls and obstacles, plus
/// the match clock and score. Arrays are fixed for the whole match; iteration is always by index.
/// </summary>
internal sealed class World
{
    private MotionBodies? _bodies;

    public World(Field field, FishState[] fish, BallState[] balls, ObstacleView[] obstacles, StaticBody[] statics)
    {
        Field = field;
        Fish = fish;
        Balls = balls;
        Obstacles = obstacles;
        Statics = statics;
    }

    /// <summary>The pool: bounds, walls, goal blocks, goal mouths.</summary>
    public Field Field { get; }

    /// <summary>Every fish by index (fishN).</summary>
    public FishState[] Fish { get; }

    /// <summary>Every ball by index (ballN).</summary>
    public BallState[] Balls { get; }

    /// <summary>Obstacle descriptions by index (obstacleN).</summary>
    public ObstacleView[] Obstacles { get; }

    /// <summary>Obstacles (first, obstacleN = index) then goal blocks (goalBlockN = index − obstacle count).</summary>
    public StaticBody[] Statics { get; }

    /// <summary>The bodies as the motion stepper holds them (created with the default broad phase when first needed).</summary>
    public MotionBodies Bodies
    {
        get => _bodies ??= new MotionBodies(this, Collision.BroadPhase.BroadPhaseKind.UniformGrid);
        set => _bodies = value;
    }

    /// <summary>Cycles completed.</summary>
    public int Cycle { get; set; }

    /// <summary>Goals scored by team 0 and team 1.</summary>
    public int[] Goals { get; } = new int[2];

    /// <summary>Match time in seconds, cycles × 0.1 (exact decimal multiple, no drift).</summary>
    public double Time => Cycle * 0.1;

    /// <summary>Number of fish of a team.</summary>
    public int CountTeam(int team)
    {
        int n = 0;
        foreach (var f in Fish)
        {
            n += f.Team == team ? 1 : 0;
        }

        return n;
    }
}
