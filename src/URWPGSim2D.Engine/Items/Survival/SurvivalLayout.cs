namespace URWPGSim2D.Engine.Items.Survival;

/// <summary>
/// The field of 生存挑战 (survival), as the original's <c>MatchTransfer</c> sets it up: a
/// 4500 × 3000 pool without goal blocks or balls, three squares 400 × 400 in a column across the
/// middle, and two sides of four fish. The hunting side plays from the left: its fish 0 at
/// (−1770, 0) (the left wall + three body lengths) facing right, its fish 1–3 parked off the field
/// below the bottom wall. The hunted side plays from the right, facing left: its fish 0 at (450, 0)
/// and its fish 1–3 (the prey) at (1600, −800), (1600, 0), (1600, 800). A caught prey fish j is
/// parked off the field at (2415 − 300 j, 1591).
/// </summary>
internal static class SurvivalLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 4500f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 3000f;

    /// <summary>Side of each square obstacle, mm.</summary>
    public const float SquareSide = 400f;

    /// <summary>Fish per team.</summary>
    public const int FishPerTeam = 4;

    /// <summary>The highest speed gear of fish 1–3 of either team (the prey), the original's cap.</summary>
    public const int PreyMaxVCode = 8;

    /// <summary>Catches that end a half.</summary>
    public const int CatchesPerHalf = 3;

    /// <summary>Square centres, in the original's order (obs1 … obs3).</summary>
    public static readonly Vector2[] Squares = [new(0f, 0f), new(0f, -700f), new(0f, 700f)];

    /// <summary>Start poses of the hunting side's fish 0–3 (heading 0); fish 1–3 are parked there.</summary>
    public static readonly Vector2[] Hunters = [new(-1770f, 0f), new(-2115f, 1591f), new(-1715f, 1591f), new(-1315f, 1591f)];

    /// <summary>Start poses of the hunted side's fish 0–3 (heading π); fish 1–3 are the prey.</summary>
    public static readonly Vector2[] Hunted = [new(450f, 0f), new(1600f, -800f), new(1600f, 0f), new(1600f, 800f)];

    /// <summary>Where a caught prey fish (its index <paramref name="j"/> = 1…3 within its team) is parked, mm.</summary>
    public static Vector2 CaughtPlace(int j) => new(2415f - (300f * j), 1591f);

    /// <summary>
    /// The scenario of the first half: team 0 hunts from the left, team 1 is hunted on the right.
    /// Fish order: team 0's four, then team 1's four.
    /// </summary>
    public static ScenarioDefinition Scenario()
    {
        var fish = new List<FishDefinition>(2 * FishPerTeam);
        for (int j = 0; j < FishPerTeam; j++)
        {
            fish.Add(new FishDefinition(0, Hunters[j], 0f, "demo", Decision.Stop));
        }

        for (int j = 0; j < FishPerTeam; j++)
        {
            fish.Add(new FishDefinition(1, Hunted[j], System.MathF.PI, "demo", Decision.Stop));
        }

        var obstacles = AxisRectangles.AddAt(new List<ObstacleDefinition>(Squares.Length), Squares, SquareSide, SquareSide);
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish = fish,
            Balls = [],
            Obstacles = obstacles,
        };
    }
}
