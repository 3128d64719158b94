namespace URWPGSim2D.Engine.Items.SynchronisedSwimming;

/// <summary>
/// The field of 花样游泳 (synchronised swimming), as the original's
/// <c>MatchSynchronisedSwimming</c> sets it up: a 4500 × 3000 pool without goal blocks, balls or
/// obstacles and one team of ten fish at random start poses: x an integer in [−1916, 1916)
/// (the side walls, the goal depth 150 and the fish's collision-model radius 184 in from them),
/// z an integer in [−1316, 1316), the heading a whole number of degrees in [0, 360). The poses are
/// drawn from the match's seed, and a fish whose centre would come within two collision radii of
/// one already placed is drawn again.
/// </summary>
internal static class SynchronisedSwimmingLayout
{
    /// <summary>Field length along X, mm.</summary>
    public const float FieldLength = 4500f;

    /// <summary>Field width along Z, mm.</summary>
    public const float FieldWidth = 3000f;

    /// <summary>Fish in the team.</summary>
    public const int FishCount = 10;

    /// <summary>The fish's collision-model radius in the original, (160 + 88 + 66 + 55) / 2 in integer mm.</summary>
    public const int FishRadius = 184;

    /// <summary>Smallest start x (inclusive), mm: −2250 + 150 + 184.</summary>
    public const int MinX = -1916;

    /// <summary>Largest start x (exclusive), mm.</summary>
    public const int MaxX = 1916;

    /// <summary>Smallest start z (inclusive), mm: −1500 + 184.</summary>
    public const int MinZ = -1316;

    /// <summary>Largest start z (exclusive), mm.</summary>
    public const int MaxZ = 1316;

    /// <summary>The start poses of the ten fish for a seed.</summary>
    public static (Vector2 Position, float Heading)[] Poses(ulong seed)
    {
        var random = new SeededRandom(seed ^ 0x53594E43UL);
        var poses = new (Vector2 Position, float Heading)[FishCount];
        for (int i = 0; i < poses.Length; i++)
        {
            Vector2 p;
            do
            {
                p = new Vector2(Next(random, MinX, MaxX), Next(random, MinZ, MaxZ));
            }
            while (TooClose(poses.AsSpan(0, i), p));

            poses[i] = (p, Next(random, 0, 360) * MathF.PI / 180f);
        }

        return poses;
    }

    /// <summary>The scenario for a seed: the ten fish at their random poses, every one on the demo.</summary>
    public static ScenarioDefinition Scenario(ulong seed)
    {
        var fish = new List<FishDefinition>(FishCount);
        foreach (var (position, heading) in Poses(seed))
        {
            fish.Add(new FishDefinition(0, position, heading, "demo", Decision.Stop));
        }

        return new ScenarioDefinition
        {
            FieldLength = FieldLength,
            FieldWidth = FieldWidth,
            GoalBlocks = false,
            Fish = fish,
            Balls = [],
            Obstacles = [],
        };
    }

    /// <summary>An integer in [min, max) from the generator.</summary>
    public static int Next(SeededRandom random, int min, int max) => min + (int)(random.NextUnit() * (max - min));

    private static bool TooClose(ReadOnlySpan<(Vector2 Position, float Heading)> placed, Vector2 p)
    {
        foreach (var (q, _) in placed)
        {
            if (Vector2.Distance(p, q) < 2 * FishRadius)
            {
                return true;
            }
        }

        return false;
    }
}
