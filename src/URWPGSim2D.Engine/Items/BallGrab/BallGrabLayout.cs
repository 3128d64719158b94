using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items.BallGrab;

/// <summary>
/// The numbers of 抢球博弈 (the original's <c>TheNewMatch2V2BallRace</c>, Match/TheNewMatch2V2.cs):
/// field 3000 × 2000 without goal blocks, r = 58 (the standard ball) and goal depth 150 as the
/// original's formulas use them. Each end has a goal box of three rectangles open toward its end
/// wall: two bars 3r × depth/3 (174 × 50) at x = ±(1500 − 15r/2) = ±1065, z = ±(4r + 2·150) = ±532,
/// and a back wall r/2 × 153r/8 (29 × 1109, integer mm as the original) at x = ±(1500 − 37r/4) = ±964.
/// A ball is in a box when it lies wholly within the bars' x extent and between their inner faces.
/// </summary>
internal static class BallGrabLayout
{
    /// <summary>Radius the original's formulas are written in (the standard ball), mm.</summary>
    public const int R = 58;

    /// <summary>Goal depth of the field configuration, mm.</summary>
    public const int GoalDepth = 150;

    /// <summary>Half length of the field, mm.</summary>
    public const int HalfLength = 1500;

    /// <summary>Bar length along x (3r), mm.</summary>
    public const int BarLength = 3 * R;

    /// <summary>Bar width along z (depth / 3), mm.</summary>
    public const int BarWidth = GoalDepth / 3;

    /// <summary>|x| of the bars' centres (1500 − 15r/2 in integer mm), mm.</summary>
    public const int BarX = HalfLength - (15 * R / 2);

    /// <summary>|z| of the bars' centres (4r + 2·depth), mm.</summary>
    public const int BarZ = (4 * R) + (2 * GoalDepth);

    /// <summary>Back wall length along x (r/2), mm.</summary>
    public const int BackLength = R / 2;

    /// <summary>Back wall width along z (153r/8 in integer mm), mm.</summary>
    public const int BackWidth = 153 * R / 8;

    /// <summary>|x| of the back walls' centres (1500 − 37r/4 in integer mm), mm.</summary>
    public const int BackX = HalfLength - (37 * R / 4);

    /// <summary>Inner |x| of a box (the bars' inner ends), mm.</summary>
    public const float BoxInnerX = BarX - (BarLength / 2);

    /// <summary>Outer |x| of a box (the bars' outer ends), mm.</summary>
    public const float BoxOuterX = BarX + (BarLength / 2);

    /// <summary>|z| of a box's inner faces (the bars' inner faces), mm.</summary>
    public const float BoxHalfWidth = BarZ - (BarWidth / 2);

    /// <summary>Ball radii by index: three small, four large, two standard.</summary>
    public static readonly float[] Radii = [38, 38, 38, 78, 78, 78, 78, 58, 58];

    /// <summary>Ball values by index (3 for the small, 1 for the large, 2 for the standard balls).</summary>
    public static readonly int[] Values = [3, 3, 3, 1, 1, 1, 1, 2, 2];

    /// <summary>Ball start positions by index.</summary>
    public static readonly Vector2[] BallStarts =
    [
        new(0, -120), new(0, 0), new(0, 120),
        new(-1420, -920), new(1420, -920), new(1420, 920), new(-1420, 920),
        new(0, -920), new(0, 920),
    ];

    /// <summary>Whether a ball lies wholly inside the goal box on side <paramref name="side"/> (−1 left, +1 right).</summary>
    public static bool InBox(Vector2 center, float radius, int side)
    {
        float x = center.X * side;
        return x - radius >= BoxInnerX && x + radius <= BoxOuterX
            && center.Y + radius <= BoxHalfWidth && center.Y - radius >= -BoxHalfWidth;
    }

    /// <summary>The four fish at cycle 0 (every one on the demo): team 0 at (−(1500 − 6 × 160), ±3 × 45) facing +x, team 1 mirrored facing −x.</summary>
    public static List<FishDefinition> StartFish()
    {
        FishSize size = FishSize.Default;
        float x = HalfLength - (size.Length * 6f);
        float z = size.Width * 3f;
        return
        [
            new(0, new Vector2(-x, z), 0f, "demo", Decision.Stop),
            new(0, new Vector2(-x, -z), 0f, "demo", Decision.Stop),
            new(1, new Vector2(x, z), System.MathF.PI, "demo", Decision.Stop),
            new(1, new Vector2(x, -z), System.MathF.PI, "demo", Decision.Stop),
        ];
    }

    /// <summary>The six rectangles of the two goal boxes in the original's order: the bars, then the back walls.</summary>
    public static List<ObstacleDefinition> BoxObstacles() =>
    [
        Rectangle(-BarX, BarZ, BarLength, BarWidth),
        Rectangle(-BarX, -BarZ, BarLength, BarWidth),
        Rectangle(BarX, BarZ, BarLength, BarWidth),
        Rectangle(BarX, -BarZ, BarLength, BarWidth),
        Rectangle(-BackX, 0, BackLength, BackWidth),
        Rectangle(BackX, 0, BackLength, BackWidth),
    ];

    /// <summary>The goal boxes as trace zones (team 0's at the left end, team 1's at the right).</summary>
    public static List<TraceZone> BoxZones() =>
    [
        TraceZone.Box("goal-box", 0, new Vector2(-BoxOuterX, -BoxHalfWidth), new Vector2(-BoxInnerX, BoxHalfWidth), team: 0),
        TraceZone.Box("goal-box", 1, new Vector2(BoxInnerX, -BoxHalfWidth), new Vector2(BoxOuterX, BoxHalfWidth), team: 1),
    ];

    private static ObstacleDefinition Rectangle(float x, float z, float length, float width) =>
        new(ObstacleKind.Rectangle, new Vector2(x, z), length, width, 0f, 0f);
}
