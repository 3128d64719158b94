namespace URWPGSim2D.Engine.Items.RelayWithBall;

/// <summary>
/// The field of 带球接力 (relay with a ball), as the original's <c>SpeedRelayWithBallIn12Meter</c>
/// sets it up from the field's numbers (length 3000, width 2000, goal depth 150, goal width 400): the
/// pool without goal blocks; three rectangles forming an I lying on its side — two arms
/// 3000 − 2 × 150 − 2 × 1.5 × 400 = 1500 long and 1.5 × 150 = 225 wide at z = ∓(1000 − 400 − 112.5)
/// = ∓487.5, and a post 400 × (2000 − 2 × 225 − 2 × 400) = 400 × 750 at the centre. The arms leave a
/// channel 400 wide along the top and the bottom wall; between the arms, each side of the post, is a
/// pocket. One ball of radius 58 in the left pocket's top right corner, at
/// (−400 / 2 − 58 − 10, −1000 + 400 + 225 + 58) = (−268, −317); fish 0 at
/// (−1500 + 2 × 160 + 45, 0) = (−1135, 0) facing +x, fish 1 at (1135, 0) facing −x.
/// </summary>
internal static class RelayWithBallLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 3000f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 2000f;

    /// <summary>Goal depth, mm.</summary>
    public const float GoalDepth = 150f;

    /// <summary>Goal width, mm.</summary>
    public const float GoalWidth = 400f;

    /// <summary>Ball radius, mm.</summary>
    public const float BallRadius = 58f;

    /// <summary>The fish's body length in the original, mm.</summary>
    public const float BodyLength = 160f;

    /// <summary>The fish's body width in the original, mm.</summary>
    public const float BodyWidth = 45f;

    /// <summary>The arms' length along x, mm.</summary>
    public const float ArmLength = FieldLength - (2f * GoalDepth) - (2f * 1.5f * GoalWidth);

    /// <summary>The arms' width along z, mm.</summary>
    public const float ArmWidth = 1.5f * GoalDepth;

    /// <summary>|z| of the arms' centres, mm.</summary>
    public const float ArmZ = (FieldWidth / 2f) - GoalWidth - (ArmWidth / 2f);

    /// <summary>The post's width along z, mm.</summary>
    public const float PostWidth = FieldWidth - (2f * ArmWidth) - (2f * GoalWidth);

    /// <summary>
    /// The rules' |x| bound of the pockets and the channels (1500 − 150 − 1.5 × 400 − 58 = 692): a ball
    /// is in a pocket within it, a fish or ball is in a channel within it, mm.
    /// </summary>
    public const float InnerX = (FieldLength / 2f) - GoalDepth - (1.5f * GoalWidth) - BallRadius;

    /// <summary>The rules' |z| bound of a ball in a pocket (1000 − 400 − 225 − 58 = 317), mm.</summary>
    public const float PocketZ = (FieldWidth / 2f) - GoalWidth - ArmWidth - BallRadius;

    /// <summary>The rules' |z| beyond which a fish or ball is in a channel (1000 − 400 + 58 = 658), mm.</summary>
    public const float ChannelZ = (FieldWidth / 2f) - GoalWidth + BallRadius;

    /// <summary>The ball's start, mm (the left pocket); mirrored in x, where a ball fouling on the way left is put back.</summary>
    public static readonly Vector2 BallStart = new((-GoalWidth / 2f) - BallRadius - 10f, (-FieldWidth / 2f) + GoalWidth + ArmWidth + BallRadius);

    /// <summary>The two fish's start positions, mm (headings 0 and π).</summary>
    public static readonly Vector2[] FishStarts =
    [
        new((-FieldLength / 2f) + (2f * BodyLength) + BodyWidth, 0f),
        new((FieldLength / 2f) - (2f * BodyLength) - BodyWidth, 0f),
    ];

    /// <summary>The three rectangles in the original's order (top arm, post, bottom arm): centre, length along x, width along z.</summary>
    public static readonly (Vector2 Centre, float Length, float Width)[] Obstacles =
    [
        (new(0f, -ArmZ), ArmLength, ArmWidth),
        (Vector2.Zero, GoalWidth, PostWidth),
        (new(0f, ArmZ), ArmLength, ArmWidth),
    ];

    /// <summary>The item's scenario: one team of two fish, obstacles 0–2 in the original's order.</summary>
    public static ScenarioDefinition Scenario()
    {
        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish =
            [
                new FishDefinition(0, FishStarts[0], 0f, "demo", Decision.Stop),
                new FishDefinition(0, FishStarts[1], System.MathF.PI, "demo", Decision.Stop),
            ],
            Balls = [new BallDefinition(BallStart, Vector2.Zero, BallRadius)],
            Obstacles = AxisRectangles.Obstacles(Obstacles),
        };
    }

    /// <summary>Whether a ball centre lies in the pocket on side <paramref name="side"/> (+1 right, −1 left) by the rules' bounds.</summary>
    public static bool InPocket(Vector2 ball, int side)
    {
        float x = ball.X * side;
        return x > 0f && x < InnerX && System.MathF.Abs(ball.Y) < PocketZ;
    }

    /// <summary>Whether a centre lies in the top (<paramref name="top"/>) or bottom channel by the rules' bounds.</summary>
    public static bool InChannel(Vector2 p, bool top) =>
        System.MathF.Abs(p.X) < InnerX && (top ? p.Y < -(FieldWidth / 2f) + GoalWidth - BallRadius : p.Y > ChannelZ);
}
