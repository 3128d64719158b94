namespace URWPGSim2D.Engine.Items.Rescue;

/// <summary>
/// The field of 急速救援 (quick rescue), as the original's <c>MatchRescue</c> sets it up: a
/// 4500 × 3000 pool without goal blocks, five walls 100 × 1100 (a slalom across the middle), two
/// balls of radius 58 in the left half and the rescue zone at the right end. The rescuing side
/// (two fish) starts at x = 1350 facing left; the other side has one fish at (−1350, 0) facing
/// right and its second fish parked off the field at (−2115, 1591).
/// </summary>
internal static class RescueLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 4500f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 3000f;

    /// <summary>Ball radius, mm (the original's default ball).</summary>
    public const float BallRadius = 58f;

    /// <summary>Wall length along X (its heading is 0), mm.</summary>
    public const float WallLength = 100f;

    /// <summary>Wall width along Z, mm.</summary>
    public const float WallWidth = 1100f;

    /// <summary>The rescue zone: a ball whose centre is inside (bounds included) is rescued.</summary>
    public static readonly Vector2 ZoneMin = new(1850f, -500f);

    /// <summary>The rescue zone's far corner.</summary>
    public static readonly Vector2 ZoneMax = new(2250f, 500f);

    /// <summary>Where the opponent's second fish is parked (off the field, frozen), mm.</summary>
    public static readonly Vector2 ParkedFish = new(-2115f, 1591f);

    /// <summary>Wall centres, in the original's order (obs1 … obs5).</summary>
    public static readonly Vector2[] Walls =
    [
        new(0f, 0f), new(550f, 950f), new(-550f, 950f), new(550f, -950f), new(-550f, -950f),
    ];

    /// <summary>Ball start positions (ball 0, ball 1), mm.</summary>
    public static readonly Vector2[] Balls = [new(-1350f, 1050f), new(-1350f, -1050f)];

    /// <summary>Start positions of the rescuing side's fish 0 and 1 (heading π), mm.</summary>
    public static readonly Vector2[] Rescuers = [new(1350f, 700f), new(1350f, -700f)];

    /// <summary>Start position of the opponent's active fish 0 (heading 0), mm.</summary>
    public static readonly Vector2 Opponent = new(-1350f, 0f);

    /// <summary>Whether a ball centre lies in the rescue zone.</summary>
    public static bool InZone(Vector2 centre) =>
        centre.X >= ZoneMin.X && centre.X <= ZoneMax.X && centre.Y >= ZoneMin.Y && centre.Y <= ZoneMax.Y;

    /// <summary>
    /// The scenario of the first half: team 0 rescues (fish 0, 1 at x = 1350), team 1's fish 0
    /// defends from (−1350, 0) and its fish 1 is parked. Fish order: team 0's two, then team 1's two.
    /// </summary>
    public static ScenarioDefinition Scenario()
    {
        var fish = new List<FishDefinition>(4);
        foreach (var (position, heading) in Poses(rescuer: 0))
        {
            fish.Add(new FishDefinition(fish.Count < 2 ? 0 : 1, position, heading, "demo", Decision.Stop));
        }

        var obstacles = AxisRectangles.AddAt(new List<ObstacleDefinition>(Walls.Length), Walls, WallLength, WallWidth);
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish = fish,
            Balls = [new BallDefinition(Balls[0], Vector2.Zero, BallRadius), new BallDefinition(Balls[1], Vector2.Zero, BallRadius)],
            Obstacles = obstacles,
        };
    }

    /// <summary>
    /// Start poses of the four fish (team 0's fish 0, 1, then team 1's fish 0, 1) when
    /// <paramref name="rescuer"/> is the rescuing team.
    /// </summary>
    public static (Vector2 Position, float Heading)[] Poses(int rescuer)
    {
        var rescuing = new[] { (Rescuers[0], System.MathF.PI), (Rescuers[1], System.MathF.PI) };
        var opposing = new[] { (Opponent, 0f), (ParkedFish, 0f) };
        return rescuer == 0
            ? [rescuing[0], rescuing[1], opposing[0], opposing[1]]
            : [opposing[0], opposing[1], rescuing[0], rescuing[1]];
    }
}
