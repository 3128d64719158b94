namespace URWPGSim2D.Engine.Items.PushBallViaChannel;

/// <summary>
/// The field of 协作过孔 (two fish push a ball through the channels), as the original's
/// <c>TwoFishPushBallViaChannel</c> sets it up: the standard 3000 × 2000 pool with goal blocks, three
/// walls depth × (2000 − goal width) = 150 × 1600 at x = (3000 − 2 × 150) / 4 = 675, 0 and −675,
/// reaching alternately from the bottom wall (z 200 ± 800, the channel above them) and from the top
/// wall (z −200 ± 800, the channel below it); one ball of radius 58 at (1500 − 58, 0), in the right
/// goal mouth; two fish at x = −1500 + 2 × 160 + 150 = −1030, z = 1000 − 16 × 45 = 280 and
/// 1000 − 6 × 45 = 730, each facing a random whole degree.
/// </summary>
internal static class PushBallViaChannelLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 3000f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 2000f;

    /// <summary>Goal depth (the walls' length along x), mm.</summary>
    public const float GoalDepth = 150f;

    /// <summary>Goal width, mm.</summary>
    public const float GoalWidth = 400f;

    /// <summary>Ball radius, mm.</summary>
    public const float BallRadius = 58f;

    /// <summary>The fish's body length in the original, mm.</summary>
    public const float BodyLength = 160f;

    /// <summary>The fish's body width in the original, mm.</summary>
    public const float BodyWidth = 45f;

    /// <summary>The walls' width along z (field width − goal width), mm.</summary>
    public const float WallWidth = FieldWidth - GoalWidth;

    /// <summary>|x| of the outer walls' centres ((field length − 2 × goal depth) / 4), mm.</summary>
    public const float WallX = (FieldLength - (2f * GoalDepth)) / 4f;

    /// <summary>The ball's start, mm.</summary>
    public static readonly Vector2 BallStart = new((FieldLength / 2f) - BallRadius, 0f);

    /// <summary>The two fish's start positions, mm.</summary>
    public static readonly Vector2[] FishStarts =
    [
        new((-FieldLength / 2f) + (2f * BodyLength) + GoalDepth, (FieldWidth / 2f) - (16f * BodyWidth)),
        new((-FieldLength / 2f) + (2f * BodyLength) + GoalDepth, (FieldWidth / 2f) - (6f * BodyWidth)),
    ];

    /// <summary>The three walls in the original's order (right, middle, left): centre, length along x, width along z.</summary>
    public static readonly (Vector2 Centre, float Length, float Width)[] Walls =
    [
        (new(WallX, (FieldWidth / 2f) - (WallWidth / 2f)), GoalDepth, WallWidth),
        (new(0f, (-FieldWidth / 2f) + (WallWidth / 2f)), GoalDepth, WallWidth),
        (new(-WallX, (FieldWidth / 2f) - (WallWidth / 2f)), GoalDepth, WallWidth),
    ];

    /// <summary>
    /// The lines the ball passes, stage by stage: wall i's left face (the original's vertex 0) for
    /// stages 1–3, the left goal line (−1500 + 150) for stage 4. The ball is past when its centre +
    /// radius is less than the line.
    /// </summary>
    public static readonly float[] StageLines =
    [
        WallX - (GoalDepth / 2f),
        -GoalDepth / 2f,
        -WallX - (GoalDepth / 2f),
        (-FieldLength / 2f) + GoalDepth,
    ];

    /// <summary>The start headings of the two fish for a seed: whole degrees 0–359, drawn as the original's <c>Random.Next(0, 360)</c>.</summary>
    public static float[] Headings(ulong seed)
    {
        var random = new SeededRandom(seed ^ 0x43484E4CUL);
        float[] headings = new float[2];
        for (int i = 0; i < headings.Length; i++)
        {
            headings[i] = (int)(random.NextUnit() * 360) * System.MathF.PI / 180f;
        }

        return headings;
    }

    /// <summary>The item's scenario for a seed: one team of two fish, walls 0–2 in the original's order.</summary>
    public static ScenarioDefinition Scenario(ulong seed)
    {
        float[] headings = Headings(seed);
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = true,
            Fish =
            [
                new FishDefinition(0, FishStarts[0], headings[0], "demo", Decision.Stop),
                new FishDefinition(0, FishStarts[1], headings[1], "demo", Decision.Stop),
            ],
            Balls = [new BallDefinition(BallStart, Vector2.Zero, BallRadius)],
            Obstacles = AxisRectangles.Obstacles(Walls),
        };
    }
}
