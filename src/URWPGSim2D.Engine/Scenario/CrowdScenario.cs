namespace URWPGSim2D.Engine.Scenario;

/// <summary>
/// A crowded research scene of any size at the default match's density: per 6 m² of pool (the
/// default 3000 × 2000 mm field) 4 fish, 9 balls and 4 obstacles, so the pool grows with the count
/// (aspect 3 : 2, goal blocks on). Bodies start on a jittered lattice without overlaps; fish have
/// random headings and fixed random decisions (speed gear 4–15, any turn gear), so they swim in
/// circles of many radii and meet balls, obstacles, walls and each other; balls start at 0–600
/// mm/s in random directions; obstacles are rectangles and round ones of the default sizes. Noise
/// on. The same count and seed give the same scene (SplitMix64).
/// </summary>
public static class CrowdScenario
{
    /// <summary>Smallest count of fish and balls.</summary>
    public const int MinimumMovers = 13;

    /// <summary>The scene with <paramref name="movers"/> fish and balls.</summary>
    /// <exception cref="ArgumentException"><paramref name="movers"/> is below <see cref="MinimumMovers"/>.</exception>
    public static ScenarioDefinition Create(int movers, ulong seed = 1, int cycles = 3000)
    {
        if (movers < MinimumMovers)
        {
            throw new ArgumentException($"must be at least {MinimumMovers}, got {movers}", nameof(movers));
        }

        int fishCount = (int)Math.Round(movers * 4.0 / 13.0);
        int ballCount = movers - fishCount;
        int obstacleCount = (int)Math.Round(movers * 4.0 / 13.0);
        double area = movers * (3000.0 * 2000.0 / 13.0);
        float length = (float)Math.Round(Math.Sqrt(area * 1.5));
        float width = (float)Math.Round(area / length);

        // One lattice cell per body, in a random order of cells.
        int bodies = fishCount + ballCount + obstacleCount;
        int columns = (int)Math.Ceiling(Math.Sqrt(bodies * 1.5));
        int rows = (int)Math.Ceiling(bodies / (double)columns);
        float cellX = (length - 300f) / columns;
        float cellZ = (width - 100f) / rows;
        var random = new SeededRandom(seed * 0x9E3779B97F4A7C15UL + (ulong)movers);
        int[] cells = Shuffled(columns * rows, random);
        int next = 0;
        Vector2 Spot(float margin)
        {
            int cell = cells[next++];
            Vector2 corner = new((-length / 2f) + 150f + ((cell % columns) * cellX), (-width / 2f) + 50f + ((cell / columns) * cellZ));
            Vector2 free = new(MathF.Max(0f, cellX - (2f * margin)), MathF.Max(0f, cellZ - (2f * margin)));
            return corner + new Vector2(margin) + new Vector2((float)random.NextUnit() * free.X, (float)random.NextUnit() * free.Y);
        }

        var fish = new List<FishDefinition>(fishCount);
        for (int i = 0; i < fishCount; i++)
        {
            var decision = new Decision(4 + (int)(random.NextUnit() * 12), (int)(random.NextUnit() * 16));
            fish.Add(new FishDefinition(i % 2, Spot(MathF.Min(cellX, cellZ) / 2f), random.NextSigned() * MathF.PI, "fixed", decision));
        }

        var balls = new List<BallDefinition>(ballCount);
        for (int i = 0; i < ballCount; i++)
        {
            float speed = (float)random.NextUnit() * 600f;
            float angle = random.NextSigned() * MathF.PI;
            balls.Add(new BallDefinition(Spot(60f), new Vector2(MathF.Cos(angle), MathF.Sin(angle)) * speed, 58f));
        }

        var obstacles = new List<ObstacleDefinition>(obstacleCount);
        for (int i = 0; i < obstacleCount; i++)
        {
            obstacles.Add(i % 2 == 0
                ? new ObstacleDefinition(ObstacleKind.Rectangle, Spot(75f), 100f, 100f, random.NextSigned() * MathF.PI, 58f)
                : new ObstacleDefinition(ObstacleKind.Round, Spot(60f), 100f, 100f, 0f, 58f));
        }

        return new ScenarioDefinition
        {
            FieldLength = length,
            FieldWidth = width,
            GoalBlocks = true,
            Cycles = cycles,
            Seed = seed,
            Noise = true,
            Fish = fish,
            Balls = balls,
            Obstacles = obstacles,
        };
    }

    private static int[] Shuffled(int count, SeededRandom random)
    {
        var order = new int[count];
        for (int i = 0; i < count; i++)
        {
            order[i] = i;
        }

        for (int i = count - 1; i > 0; i--)
        {
            int j = (int)(random.NextUnit() * (i + 1));
            (order[i], order[j]) = (order[j], order[i]);
        }

        return order;
    }
}
