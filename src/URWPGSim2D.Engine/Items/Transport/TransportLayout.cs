namespace URWPGSim2D.Engine.Items.Transport;

/// <summary>
/// The field of 水中搬运 (underwater transport), as the original's <c>Match1V1Moving</c> sets it
/// up: a 3000 × 2000 pool without goal blocks or obstacles, one team of two fish, six balls of
/// radius 58 in a triangle pointing left (rows of 1, 2 and 3 at x = 160 (row + 3)) and six holes in
/// a triangle pointing right (rows at x = −240 (row − 1), 160 mm apart across, drawn with radius
/// 80). Ball i belongs in hole i: it is in when its centre is less than 22 mm from the hole's.
/// </summary>
internal static class TransportLayout
{
    /// <summary>Field length along X, mm (the original's default field).</summary>
    public const float FieldLength = 3000f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 2000f;

    /// <summary>Ball radius, mm (the original's default ball).</summary>
    public const float BallRadius = 58f;

    /// <summary>Radius the original draws the holes with, mm (its <c>MovingCircleRadius</c>).</summary>
    public const float HoleRadius = 80f;

    /// <summary>A ball is in its hole when its centre is less than this from the hole's centre, mm.</summary>
    public const float Tolerance = 22f;

    /// <summary>Number of balls and holes.</summary>
    public const int Count = 6;

    /// <summary>Start positions of the fish 0 and 1 (heading 0): the left wall + 3 body lengths, ±3 body widths.</summary>
    public static readonly Vector2[] FishStarts = [new(-1020f, 135f), new(-1020f, -135f)];

    /// <summary>Start positions of balls 0–5, mm.</summary>
    public static readonly Vector2[] Balls = Triangle(row => 160f * (row + 3), BallRadius * 2f);

    /// <summary>Centres of holes 0–5, mm.</summary>
    public static readonly Vector2[] Holes = Triangle(row => -3f * (row - 1) * HoleRadius, HoleRadius * 2f);

    /// <summary>Whether a ball centre is in its hole: squared distance below 22² = 484 (the original's test).</summary>
    public static bool InHole(Vector2 centre, Vector2 hole) => Vector2.DistanceSquared(centre, hole) < Tolerance * Tolerance;

    /// <summary>The scenario: the two fish facing +x, the six balls at rest.</summary>
    public static ScenarioDefinition Scenario()
    {
        var balls = new List<BallDefinition>(Count);
        foreach (var b in Balls)
        {
            balls.Add(new BallDefinition(b, Vector2.Zero, BallRadius));
        }

        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish = [new FishDefinition(0, FishStarts[0], 0f, "demo", Decision.Stop), new FishDefinition(0, FishStarts[1], 0f, "demo", Decision.Stop)],
            Balls = balls,
            Obstacles = [],
        };
    }

    // Rows 1–3 of 1, 2 and 3 points, numbered row by row from −z: row r at x(r), its j-th point at z = (2 (j − 1) − (r − 1)) · step.
    private static Vector2[] Triangle(System.Func<int, float> x, float step)
    {
        var points = new Vector2[Count];
        for (int row = 1; row <= 3; row++)
        {
            for (int j = 1; j <= row; j++)
            {
                points[(row * (row - 1) / 2) + j - 1] = new Vector2(x(row), (-(row - 1) * step) + (2f * step * (j - 1)));
            }
        }

        return points;
    }
}
