namespace URWPGSim2D.Engine.Items.CrossCountry;

/// <summary>
/// The field of 障碍越野 (obstacle cross-country), as the original's <c>MatchObstacleRacing</c>
/// sets it up: a 4500 × 3000 pool without goal blocks, one fish at (1600, 0) facing left, two balls
/// of radius 58 at (−1600, ∓1200), three round obstacles of radius 80 on the centre line and four
/// 200 × 100 rectangles on x = 0 near the top and bottom walls. Ball 0's target is (1900, −1200),
/// ball 1's (1900, 1200); a ball is home when its centre is within 22 mm of its target.
/// </summary>
internal static class CrossCountryLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 4500f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 3000f;

    /// <summary>Ball radius, mm.</summary>
    public const float BallRadius = 58f;

    /// <summary>Round obstacle radius, mm.</summary>
    public const float PostRadius = 80f;

    /// <summary>Rectangle length along X (heading 0), mm.</summary>
    public const float BlockLength = 200f;

    /// <summary>Rectangle width along Z, mm.</summary>
    public const float BlockWidth = 100f;

    /// <summary>How close a ball centre must come to its target, mm (the original compares the squared distance with 484).</summary>
    public const float TargetTolerance = 22f;

    /// <summary>The fish's start position, mm (heading π).</summary>
    public static readonly Vector2 FishStart = new(1600f, 0f);

    /// <summary>Ball start positions (ball 0, ball 1), mm.</summary>
    public static readonly Vector2[] Balls = [new(-1600f, -1200f), new(-1600f, 1200f)];

    /// <summary>Target of each ball, mm.</summary>
    public static readonly Vector2[] Targets = [new(1900f, -1200f), new(1900f, 1200f)];

    /// <summary>Round obstacles (obs1 … obs3), mm.</summary>
    public static readonly Vector2[] Posts = [new(0f, 0f), new(-1000f, 0f), new(1000f, 0f)];

    /// <summary>Rectangles in the original's order (obs4, obs7, obs5, obs6), mm.</summary>
    public static readonly Vector2[] Blocks = [new(0f, 1350f), new(0f, 1050f), new(0f, -1350f), new(0f, -1050f)];

    /// <summary>Whether a ball centre is home at a target: squared distance ≤ 22².</summary>
    public static bool AtTarget(Vector2 centre, Vector2 target) =>
        Vector2.DistanceSquared(centre, target) <= TargetTolerance * TargetTolerance;

    /// <summary>The item's scenario: one team, one fish; obstacles round ones first (obstacle 0–2), then rectangles (3–6).</summary>
    public static ScenarioDefinition Scenario()
    {
        var obstacles = new List<ObstacleDefinition>(7);
        foreach (var c in Posts)
        {
            obstacles.Add(new ObstacleDefinition(ObstacleKind.Round, c, 2f * PostRadius, 2f * PostRadius, 0f, PostRadius));
        }

        AxisRectangles.AddAt(obstacles, Blocks, BlockLength, BlockWidth);
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish = [new FishDefinition(0, FishStart, System.MathF.PI, "demo", Decision.Stop)],
            Balls = [new BallDefinition(Balls[0], Vector2.Zero, BallRadius), new BallDefinition(Balls[1], Vector2.Zero, BallRadius)],
            Obstacles = obstacles,
        };
    }
}
