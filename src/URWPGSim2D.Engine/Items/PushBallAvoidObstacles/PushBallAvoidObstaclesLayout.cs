namespace URWPGSim2D.Engine.Items.PushBallAvoidObstacles;

/// <summary>
/// The field of 带球避障 (push a ball past obstacles), as the original's
/// <c>SingleFishPushBallAvoidObstacles</c> sets it up: the standard 3000 × 2000 pool without goal
/// blocks, one fish at (−1500 + 2 × 160, 0) = (−1180, 0) facing +x, one ball of radius 58 at
/// (1030, 0), and ten rectangles (heading 0, length along x): on each side a wall in two parts with
/// a gate between them closed by two small blocks, and a thin line marking the open passage along
/// the far wall (below on the left, above on the right). The black line the ball must cross
/// (wholly: its right edge at or left of it) is x = −500.
/// </summary>
internal static class PushBallAvoidObstaclesLayout
{
    /// <summary>Field length along X, mm (the original's default field).</summary>
    public const float FieldLength = 3000f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 2000f;

    /// <summary>Ball radius, mm.</summary>
    public const float BallRadius = 58f;

    /// <summary>The fish's body length in the original (<c>RoboFish.BodyLength</c>), which its rules use as a margin, mm.</summary>
    public const float BodyLength = 160f;

    /// <summary>The fish's body width in the original (<c>RoboFish.BodyWidth</c>), mm.</summary>
    public const float BodyWidth = 45f;

    /// <summary>The black line: the ball is through when its centre + radius ≤ this x, mm.</summary>
    public const float BlackLineX = -500f;

    /// <summary>The ball's start (and return) position, mm.</summary>
    public static readonly Vector2 BallStart = new(1030f, 0f);

    /// <summary>The fish's start position, mm (heading 0).</summary>
    public static readonly Vector2 FishStart = new((-FieldLength / 2f) + (2f * BodyLength), 0f);

    /// <summary>The ten rectangles in the original's order (obs1 … obs10): centre, length along x, width along z.</summary>
    public static readonly (Vector2 Centre, float Length, float Width)[] Obstacles =
    [
        (new(-480f, 650f), 10f, 700f),
        (new(-550f, 270f), 150f, 60f),
        (new(-550f, 180f), 150f, 60f),
        (new(-480f, -160f), 10f, 700f),
        (new(-480f, -510f), 150f, 3f),
        (new(480f, -650f), 10f, 700f),
        (new(550f, -270f), 150f, 60f),
        (new(550f, -180f), 150f, 60f),
        (new(480f, 160f), 10f, 700f),
        (new(480f, 510f), 150f, 3f),
    ];

    /// <summary>The item's scenario: one team of one fish, obstacles 0–9 in the original's order.</summary>
    public static ScenarioDefinition Scenario()
    {
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish = [new FishDefinition(0, FishStart, 0f, "demo", Decision.Stop)],
            Balls = [new BallDefinition(BallStart, Vector2.Zero, BallRadius)],
            Obstacles = AxisRectangles.Obstacles(Obstacles),
        };
    }
}
