namespace URWPGSim2D.Engine.Items.DoubleFishRace;

/// <summary>
/// The field of 双鱼竞速 (two fish race through holes), as the original's <c>DoubleFishRaceViaHoles</c>
/// sets it up: the standard 3000 × 2000 pool without goal blocks and three walls, heading 0, goal
/// depth 150 long along x, with h = 2000 − 6 × 45 (body width) = 1730: a centre wall 150 × 1730 at
/// the origin, leaving a hole of 135 at the top and the bottom, and two side walls 150 × 865 at
/// x = ∓(1500 − 3 × 150 / 2 − 400) = ∓875 (400 the forbidden zone's length). Team 0's fish at
/// (−1500 + 2 × 160, 0) = (−1180, 0) facing −z (up), team 1's at (1180, 0) facing +z (down): both
/// swim round the centre the same way, half a lap apart.
/// </summary>
internal static class DoubleFishRaceLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 3000f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 2000f;

    /// <summary>Goal depth (the walls' length along x), mm.</summary>
    public const float GoalDepth = 150f;

    /// <summary>The forbidden zone's length along x in the field's numbers, mm.</summary>
    public const float ForbiddenZoneLength = 400f;

    /// <summary>The fish's body length in the original, mm.</summary>
    public const float BodyLength = 160f;

    /// <summary>The fish's body width in the original, mm.</summary>
    public const float BodyWidth = 45f;

    /// <summary>The centre wall's width along z (2000 − 6 × 45), mm; the side walls are half of it.</summary>
    public const float WallWidth = FieldWidth - (6f * BodyWidth);

    /// <summary>|x| of the side walls' centres (1500 − 3 × 150 / 2 − 400, the original's integer 225), mm.</summary>
    public const float SideX = (FieldLength / 2f) - 225f - ForbiddenZoneLength;

    /// <summary>The three walls in the original's order (left, centre, right): centre, length along x, width along z.</summary>
    public static readonly (Vector2 Centre, float Length, float Width)[] Walls =
    [
        (new(-SideX, 0f), GoalDepth, WallWidth / 2f),
        (Vector2.Zero, GoalDepth, WallWidth),
        (new(SideX, 0f), GoalDepth, WallWidth / 2f),
    ];

    /// <summary>The two fish's start poses (team 0 then team 1).</summary>
    public static readonly (Vector2 Position, float Heading)[] Starts =
    [
        (new((-FieldLength / 2f) + (2f * BodyLength), 0f), -System.MathF.PI / 2f),
        (new((FieldLength / 2f) - (2f * BodyLength), 0f), System.MathF.PI / 2f),
    ];

    /// <summary>
    /// The x range in which a fish may not cross the line z = 0: from the left wall's right face
    /// (−800) to the right wall's left face (800), mm.
    /// </summary>
    public const float CrossingX = SideX - (GoalDepth / 2f);

    /// <summary>The item's scenario: two teams of one fish, walls 0–2 in the original's order.</summary>
    public static ScenarioDefinition Scenario()
    {
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish =
            [
                new FishDefinition(0, Starts[0].Position, Starts[0].Heading, "demo", Decision.Stop),
                new FishDefinition(1, Starts[1].Position, Starts[1].Heading, "demo", Decision.Stop),
            ],
            Balls = [],
            Obstacles = AxisRectangles.Obstacles(Walls),
        };
    }
}
