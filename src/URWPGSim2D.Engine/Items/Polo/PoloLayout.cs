using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Pool;

namespace URWPGSim2D.Engine.Items.Polo;

/// <summary>
/// The fields of 水球 (water polo) 1v1, 3v3 and 5v5, as the original's <c>Match1V1</c>,
/// <c>Match3V3</c> and <c>Match5V5</c> set them up: goal blocks, one ball of radius 58 at the
/// centre, goals 400 wide and 150 deep, a forbidden zone 400 × 1000 in front of each goal (the
/// zone includes the goal), a centre circle of radius 200. 1v1 and 3v3 play on 3000 × 2000, 5v5 on
/// 4500 × 3000. Start poses are written in fish body lengths L and widths W from the end lines, as
/// the original does (L = 160, W = 45 for the deployed fish).
/// </summary>
internal static class PoloLayout
{
    /// <summary>Ball radius, mm.</summary>
    public const float BallRadius = 58f;

    /// <summary>Depth of the forbidden zone beyond the goal, along X, mm.</summary>
    public const float ForbiddenZoneLength = 400f;

    /// <summary>Width of the forbidden zone along Z, mm (|z| ≤ 500).</summary>
    public const float ForbiddenZoneWidth = 1000f;

    /// <summary>Centre circle radius, mm (5v5's role lines are x = ±200).</summary>
    public const float CentreCircleRadius = 200f;

    /// <summary>Field length along X for a team size, mm.</summary>
    public static float FieldLength(int perTeam) => perTeam == 5 ? 4500f : 3000f;

    /// <summary>Field width along Z for a team size, mm.</summary>
    public static float FieldWidth(int perTeam) => perTeam == 5 ? 3000f : 2000f;

    /// <summary>
    /// Start poses of the team playing on <paramref name="leftSide"/>: fish 0 to n−1. For 5v5 the
    /// forwards (fish 3 and 4) of the team that kicks off stand 2·W off the centre line, the other
    /// team's forwards 10·W off it (the original's two kick-off set-ups).
    /// </summary>
    public static (Vector2 Position, float Heading)[] KickOffPoses(int perTeam, bool leftSide, bool kicksOff, FishSize size)
    {
        var poses = new (Vector2, float)[perTeam];
        for (int j = 0; j < perTeam; j++)
        {
            poses[j] = KickOffPose(perTeam, leftSide, kicksOff, size, j);
        }

        return poses;
    }

    /// <summary>The start pose of fish <paramref name="j"/> (0 to n−1) of the team playing on <paramref name="leftSide"/>, as <see cref="KickOffPoses"/>.</summary>
    public static (Vector2 Position, float Heading) KickOffPose(int perTeam, bool leftSide, bool kicksOff, FishSize size, int j)
    {
        float end = FieldLength(perTeam) / 2f;
        float back = end - (3f * size.Length);
        float sign = leftSide ? -1f : 1f;
        float heading = leftSide ? 0f : MathF.PI;
        float aside = (kicksOff ? 2f : 10f) * size.Width;
        return j switch
        {
            0 => (new Vector2(sign * back, 0f), heading),
            1 when perTeam >= 3 => (new Vector2(sign * back, 3f * size.Width), heading),
            2 when perTeam >= 3 => (new Vector2(sign * back, -3f * size.Width), heading),
            3 when perTeam == 5 => (new Vector2(sign * 2f * size.Length, aside), heading),
            4 when perTeam == 5 => (new Vector2(sign * 2f * size.Length, -aside), heading),
            _ => (Vector2.Zero, 0f),
        };
    }

    /// <summary>
    /// The item's scenario at kick-off: team 0 on the left (and, in 5v5, kicking off), team 1 on the
    /// right, fish of team 0 first.
    /// </summary>
    public static ScenarioDefinition Scenario(int perTeam)
    {
        if (perTeam is not (1 or 3 or 5))
        {
            throw new ArgumentOutOfRangeException(nameof(perTeam), perTeam, "water polo is played 1v1, 3v3 or 5v5");
        }

        var fish = new List<FishDefinition>(2 * perTeam);
        for (int team = 0; team < 2; team++)
        {
            foreach (var (position, heading) in KickOffPoses(perTeam, leftSide: team == 0, kicksOff: team == 0, FishSize.Default))
            {
                fish.Add(new FishDefinition(team, position, heading, "demo", Decision.Stop));
            }
        }

        return new ScenarioDefinition
        {
            FieldLength = FieldLength(perTeam),
            FieldWidth = FieldWidth(perTeam),
            GoalBlocks = true,
            Fish = fish,
            Balls = [new BallDefinition(Vector2.Zero, Vector2.Zero, BallRadius)],
            Obstacles = [],
        };
    }

    /// <summary>Whether a ball lies wholly inside the goal on a side (−1 left, +1 right): x beyond the goal line by its radius, |z| ≤ 200 − r.</summary>
    public static bool BallInGoal(Vector2 centre, float radius, float fieldLength, int side)
    {
        float line = (fieldLength / 2f) - Field.GoalDepth + radius;
        return side * centre.X >= line && MathF.Abs(centre.Y) <= (Field.GoalWidth / 2f) - radius;
    }

    /// <summary>Whether a ball lies wholly inside the forbidden zone (goal included) on a side.</summary>
    public static bool BallInForbiddenZone(Vector2 centre, float radius, float fieldLength, int side)
    {
        float line = (fieldLength / 2f) - Field.GoalDepth - ForbiddenZoneLength + radius;
        return side * centre.X >= line && MathF.Abs(centre.Y) <= (ForbiddenZoneWidth / 2f) - radius;
    }

    /// <summary>Whether a fish position (body centre) is inside the goal on a side (bounds included).</summary>
    public static bool FishInGoal(Vector2 position, float fieldLength, int side) =>
        side * position.X >= (fieldLength / 2f) - Field.GoalDepth && MathF.Abs(position.Y) <= Field.GoalWidth / 2f;

    /// <summary>Whether a fish position is inside the forbidden zone (goal included) on a side.</summary>
    public static bool FishInForbiddenZone(Vector2 position, float fieldLength, int side) =>
        side * position.X >= (fieldLength / 2f) - Field.GoalDepth - ForbiddenZoneLength && MathF.Abs(position.Y) <= ForbiddenZoneWidth / 2f;

    /// <summary>
    /// Whether the ball is in one of the four dead-ball corners: within goal depth + r + 50 of an end
    /// line and r + 50 of a side wall.
    /// </summary>
    public static bool BallInCorner(Vector2 centre, float radius, float fieldLength, float fieldWidth)
    {
        float x = (fieldLength / 2f) - Field.GoalDepth - radius - 50f;
        float z = (fieldWidth / 2f) - radius - 50f;
        return MathF.Abs(centre.X) >= x && MathF.Abs(centre.Y) >= z;
    }

    /// <summary>The free-ball spot nearest the ball: one of (±L/4, ±W/4) (the first of equals in the original's order).</summary>
    public static Vector2 FreeBallSpot(Vector2 ball, float fieldLength, float fieldWidth)
    {
        float x = MathF.Truncate(fieldLength / 2f) / 2f;
        float z = MathF.Truncate(fieldWidth / 2f) / 2f;
        Span<Vector2> spots = [new(-x, -z), new(-x, z), new(x, -z), new(x, z)];
        Vector2 best = spots[0];
        float bestDistance = Vector2.Distance(best, ball);
        for (int i = 1; i < spots.Length; i++)
        {
            float d = Vector2.Distance(spots[i], ball);
            if (d < bestDistance)
            {
                best = spots[i];
                bestDistance = d;
            }
        }

        return best;
    }

    /// <summary>The penalty spot in front of a goal (side −1 left, +1 right): on the forbidden zone's line, z = 0.</summary>
    public static Vector2 PenaltySpot(float fieldLength, int side) =>
        new(side * ((fieldLength / 2f) - Field.GoalDepth - ForbiddenZoneLength), 0f);
}
