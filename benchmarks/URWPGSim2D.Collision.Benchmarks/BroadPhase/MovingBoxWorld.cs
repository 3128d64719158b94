namespace URWPGSim2D.Collision.Benchmarks.BroadPhase;

/// <summary>
/// Frames of a world of moving boxes at the default match's density: per 6 m² of pool (the
/// 3000 × 2000 mm field) 4 fish and 9 balls, so the pool grows with the count (aspect 3:2). A
/// fish's box is its swept bounding circle for a cycle (radius 190 + 32 mm travel); a ball's is its
/// circle (58 mm) grown by its travel (0–60 mm per cycle). Fish swim at 100–317 mm/s and turn
/// slowly, balls roll at 0–600 mm/s; both bounce off the walls. <see cref="Frames"/> consecutive
/// 100 ms frames are precomputed so that a benchmark measures only the broad phase.
/// </summary>
public sealed class MovingBoxWorld
{
    /// <summary>Precomputed frames.</summary>
    public const int Frames = 16;

    /// <summary>Builds the frames for <paramref name="count"/> objects (seeded, deterministic).</summary>
    public MovingBoxWorld(int count, int seed = 1)
    {
        Count = count;
        double area = count * (3000.0 * 2000.0 / 13.0);
        float length = (float)Math.Sqrt(area * 1.5);
        float width = (float)(area / length);
        HalfSize = new Vector2(length / 2f, width / 2f);
        var random = new Random(seed);
        var position = new Vector2[count];
        var velocity = new Vector2[count];
        var radius = new float[count];
        var turn = new float[count];
        for (int i = 0; i < count; i++)
        {
            bool fish = i % 13 < 4;
            radius[i] = fish ? 190f : 58f;
            position[i] = new Vector2(Uniform(random, HalfSize.X - radius[i]), Uniform(random, HalfSize.Y - radius[i]));
            float speed = fish ? 100f + ((float)random.NextDouble() * 217f) : (float)random.NextDouble() * 600f;
            float angle = (float)(random.NextDouble() * Math.PI * 2.0);
            velocity[i] = new Vector2(MathF.Cos(angle), MathF.Sin(angle)) * speed;
            turn[i] = fish ? Uniform(random, 0.3f) : 0f;
        }

        Boxes = new Aabb[Frames][];
        for (int f = 0; f < Frames; f++)
        {
            Boxes[f] = new Aabb[count];
            for (int i = 0; i < count; i++)
            {
                float travel = velocity[i].Length() * 0.1f;
                float r = radius[i] + travel + 1f;
                Boxes[f][i] = new Aabb(position[i] - new Vector2(r), position[i] + new Vector2(r));
                var (s, c) = MathF.SinCos(turn[i] * 0.1f);
                velocity[i] = new Vector2((velocity[i].X * c) - (velocity[i].Y * s), (velocity[i].X * s) + (velocity[i].Y * c));
                position[i] += velocity[i] * 0.1f;
                Vector2 limit = HalfSize - new Vector2(radius[i]);
                if (MathF.Abs(position[i].X) > limit.X)
                {
                    velocity[i].X = -velocity[i].X;
                    position[i].X = Math.Clamp(position[i].X, -limit.X, limit.X);
                }

                if (MathF.Abs(position[i].Y) > limit.Y)
                {
                    velocity[i].Y = -velocity[i].Y;
                    position[i].Y = Math.Clamp(position[i].Y, -limit.Y, limit.Y);
                }
            }
        }
    }

    /// <summary>Number of objects.</summary>
    public int Count { get; }

    /// <summary>Half the pool's length and width, mm.</summary>
    public Vector2 HalfSize { get; }

    /// <summary>The boxes of each frame.</summary>
    public Aabb[][] Boxes { get; }

    private static float Uniform(Random random, float half) => (float)((random.NextDouble() * 2.0) - 1.0) * half;
}
