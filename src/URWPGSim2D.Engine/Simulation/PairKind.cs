namespace URWPGSim2D.Engine.Simulation;

/// <summary>The pair kinds the motion world tests (A and B index the arrays named by the kind).</summary>
public enum PairKind : byte
{
    /// <summary>Fish A, fish B (A &lt; B).</summary>
    FishFish,

    /// <summary>Fish A, ball B.</summary>
    FishBall,

    /// <summary>Ball A, ball B (A &lt; B).</summary>
    BallBall,

    /// <summary>Fish A, static body B (obstacle or goal block).</summary>
    FishStatic,

    /// <summary>Ball A, static body B.</summary>
    BallStatic,

    /// <summary>Fish A against the pool's walls.</summary>
    FishWall,

    /// <summary>Ball A against the pool's walls.</summary>
    BallWall,
}
