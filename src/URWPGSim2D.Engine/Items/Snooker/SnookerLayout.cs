using URWPGSim2D.Collision.Pool;

namespace URWPGSim2D.Engine.Items.Snooker;

/// <summary>
/// The table of 斯诺克 (water snooker), as the original's <c>MatchSnooker</c> sets it up: a
/// 4500 × 3000 pool without goal blocks; four rectangles (2025 × 150, against the top and bottom
/// walls) leave six pockets 150 wide: at both corners and in the middle of the top and bottom
/// walls. Ten balls of radius 58: reds 0–5 in a triangle right of the centre, colours 6–9 to the
/// left, placed in multiples of the fish's collision-model radius R = (L + L1 + L2 + L3) / 2 = 184
/// (integer mm, as the original). The one fish starts at (−6R, 0) facing right.
/// </summary>
internal static class SnookerLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 4500f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 3000f;

    /// <summary>Ball radius, mm.</summary>
    public const float BallRadius = 58f;

    /// <summary>The fish's collision-model radius the original places the balls with, mm (369 / 2 in integers).</summary>
    public const float ModelRadius = 184f;

    /// <summary>Number of red balls (ids 0–5); ids 6–9 are the colours.</summary>
    public const int Reds = 6;

    /// <summary>Number of balls.</summary>
    public const int BallCount = 10;

    /// <summary>Pocket width (the goal depth), mm.</summary>
    public const float PocketWidth = Field.GoalDepth;

    /// <summary>Cushion length along X: (field length − 3 pockets) / 2 = 2025 mm.</summary>
    public const float CushionLength = (FieldLength - (3f * PocketWidth)) / 2f;

    /// <summary>Cushion width along Z, mm.</summary>
    public const float CushionWidth = PocketWidth;

    /// <summary>The fish's start position, mm (heading 0).</summary>
    public static readonly Vector2 FishStart = new(-6f * ModelRadius, 0f);

    /// <summary>Cushion centres: top left, top right, bottom left, bottom right.</summary>
    public static readonly Vector2[] Cushions =
    [
        new(-(CushionLength + PocketWidth) / 2f, (-FieldWidth / 2f) + (PocketWidth / 2f)),
        new((CushionLength + PocketWidth) / 2f, (-FieldWidth / 2f) + (PocketWidth / 2f)),
        new(-(CushionLength + PocketWidth) / 2f, (FieldWidth / 2f) - (PocketWidth / 2f)),
        new((CushionLength + PocketWidth) / 2f, (FieldWidth / 2f) - (PocketWidth / 2f)),
    ];

    /// <summary>Centre z a ball must reach (or pass) to be in a top pocket: top + 150 − r = −1408.</summary>
    public const float TopPocketZ = (-FieldWidth / 2f) + PocketWidth - BallRadius;

    /// <summary>The pockets' x ranges of the ball centre: left corner (open), middle and right corner (closed).</summary>
    public static readonly (float Min, float Max)[] PocketX =
    [
        ((-FieldLength / 2f) + BallRadius, (-FieldLength / 2f) + PocketWidth - BallRadius),
        (MathF.Truncate(-PocketWidth / 2f) + BallRadius, MathF.Truncate(PocketWidth / 2f) - BallRadius),
        ((FieldLength / 2f) - PocketWidth + BallRadius, (FieldLength / 2f) - BallRadius),
    ];

    /// <summary>The value of a ball: a red is 1, colour id scores id − 4 (2, 3, 4, 5).</summary>
    public static int Value(int ball) => ball < Reds ? 1 : ball - 4;

    /// <summary>Start (and re-spot) position of a ball, mm.</summary>
    public static Vector2 Spot(int ball)
    {
        float r = BallRadius, R = ModelRadius, s = BallRadius * MathF.Sqrt(3f);
        return ball switch
        {
            0 => new(2f * R, 0f),
            1 => new((2f * R) + s, r),
            2 => new((2f * R) + s, -r),
            3 => new((2f * R) + (2f * s), 2f * r),
            4 => new((2f * R) + (2f * s), 0f),
            5 => new((2f * R) + (2f * s), -2f * r),
            6 => new(-2f * R, 0f),
            7 => new(-4f * R, 0f),
            8 => new(-6f * R, -2f * R),
            9 => new(-6f * R, 2f * R),
            _ => throw new ArgumentOutOfRangeException(nameof(ball), ball, "snooker has balls 0–9"),
        };
    }

    /// <summary>
    /// The pocket a ball centre is in: −1 top, +1 bottom, 0 none. Top wins when both hold (they
    /// cannot). Left corner bounds are open, the middle and right ones closed, as the original.
    /// </summary>
    public static int Pocket(Vector2 centre)
    {
        bool x = (centre.X > PocketX[0].Min && centre.X < PocketX[0].Max)
            || MathF.Abs(centre.X) <= PocketX[1].Max
            || (centre.X >= PocketX[2].Min && centre.X <= PocketX[2].Max);
        if (!x)
        {
            return 0;
        }

        return centre.Y <= TopPocketZ ? -1 : centre.Y >= -TopPocketZ ? 1 : 0;
    }

    /// <summary>Where the n-th (0-based) potted red is laid off the table beside a pocket row (−1 top, +1 bottom).</summary>
    public static Vector2 PottedRedPlace(int n, int row) =>
        new(PocketX[0].Max + ((5 + (2 * n)) * BallRadius), row * ((FieldWidth / 2f) + MathF.Truncate(1.5f * BallRadius)));

    /// <summary>Where the n-th potted colour (after the reds) is laid off the table.</summary>
    public static Vector2 PottedColourPlace(int n, int row) =>
        new(PocketX[2].Min - ((5 + (2 * n)) * BallRadius), row * ((FieldWidth / 2f) + MathF.Truncate(1.5f * BallRadius)));

    /// <summary>Where a wrongly potted red goes back on the table: against the right wall (top pocket) or the left wall (bottom pocket).</summary>
    public static Vector2 FoulRedPlace(int row) =>
        new(row < 0 ? (FieldLength / 2f) - BallRadius : (-FieldLength / 2f) + BallRadius, 0f);

    /// <summary>The item's scenario: one fish, ten balls, four cushions (obstacles 0–3).</summary>
    public static ScenarioDefinition Scenario()
    {
        var balls = new List<BallDefinition>(BallCount);
        for (int i = 0; i < BallCount; i++)
        {
            balls.Add(new BallDefinition(Spot(i), Vector2.Zero, BallRadius));
        }

        var cushions = AxisRectangles.AddAt(new List<ObstacleDefinition>(4), Cushions, CushionLength, CushionWidth);
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish = [new FishDefinition(0, FishStart, 0f, "demo", Decision.Stop)],
            Balls = balls,
            Obstacles = cushions,
        };
    }
}
