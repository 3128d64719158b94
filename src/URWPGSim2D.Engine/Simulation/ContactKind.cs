namespace URWPGSim2D.Engine.Simulation;

/// <summary>The pair kinds counted in the summary (goal blocks and walls are the border).</summary>
public enum ContactKind
{
    /// <summary>Fish against fish.</summary>
    FishFish,

    /// <summary>Fish against ball.</summary>
    FishBall,

    /// <summary>Fish against an obstacle.</summary>
    FishObstacle,

    /// <summary>Fish against a wall or goal block.</summary>
    FishBorder,

    /// <summary>Ball against ball.</summary>
    BallBall,

    /// <summary>Ball against an obstacle.</summary>
    BallObstacle,

    /// <summary>Ball against a wall or goal block.</summary>
    BallBorder,
}
