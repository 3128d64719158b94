using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Strategies.Tests.Sensing;

/// <summary>
/// A random snapshot (a 3000 × 2000 field, two rectangle obstacles at any heading, a round one,
/// balls and fish at any pose) and, in double, the truth about it, written apart from the library:
/// each body as a disc, a polygon (rectangles and the eight fish leaves) or the outside of one
/// border, with point-inside tests and densely sampled boundaries.
/// </summary>
internal sealed class SensedScene
{
    public const float Length = 3000f, Width = 2000f;

    /// <summary>Samples per mm of a polygon's boundary (the brute force's spacing is 1/this mm).</summary>
    public const double SamplesPerMm = 4;

    private SensedScene(MatchSnapshot snapshot, List<Truth> bodies)
    {
        Snapshot = snapshot;
        Bodies = bodies;
    }

    public MatchSnapshot Snapshot { get; }

    public List<Truth> Bodies { get; }

    /// <summary>A random scene; <paramref name="fishCount"/> fish and <paramref name="ballCount"/> balls.</summary>
    public static SensedScene Random(Random rng, int fishCount = 3, int ballCount = 4)
    {
        var obstacles = new[]
        {
            new ObstacleView(0, ObstacleKind.Rectangle, Point(rng, 900f), 100f + (300f * rng.NextSingle()), 40f + (150f * rng.NextSingle()), Angle(rng), 0f),
            new ObstacleView(1, ObstacleKind.Rectangle, Point(rng, 900f), 100f + (300f * rng.NextSingle()), 40f + (150f * rng.NextSingle()), Angle(rng), 0f),
            new ObstacleView(2, ObstacleKind.Round, Point(rng, 900f), 0f, 0f, 0f, 40f + (120f * rng.NextSingle())),
        };
        var snapshot = new MatchSnapshot(fishCount, ballCount, obstacles, Length, Width);
        snapshot.SetHeader(rng.Next(1, 6000), [0, 0]);
        for (int i = 0; i < ballCount; i++)
        {
            snapshot.BallBuffer[i] = new BallView(i, Point(rng, 900f), Vector2.Zero, 20f + (40f * rng.NextSingle()));
        }

        for (int i = 0; i < fishCount; i++)
        {
            snapshot.FishBuffer[i] = new FishView(i, i % 2, Point(rng, 1000f), Angle(rng), 0f, 0f, 160f, 30f, Decision.Stop)
            {
                Joint1 = Joint(rng),
                Joint2 = Joint(rng),
                Joint3 = Joint(rng),
            };
        }

        return new SensedScene(snapshot, TruthOf(snapshot));
    }

    /// <summary>The truth of a snapshot's bodies, in the sensor's order (borders, obstacles, balls, fish).</summary>
    public static List<Truth> TruthOf(MatchSnapshot snapshot)
    {
        var bodies = new List<Truth>();
        double hx = snapshot.FieldLength / 2.0, hz = snapshot.FieldWidth / 2.0;
        for (int side = 0; side < 4; side++)
        {
            bodies.Add(Truth.Border(side, hx, hz));
        }

        foreach (var o in snapshot.Obstacles)
        {
            if (o.Kind == ObstacleKind.Round)
            {
                bodies.Add(Truth.Disc(SensedBody.Obstacle(o.Index), o.Center, o.Radius));
                continue;
            }

            double c = Math.Cos(o.Heading), s = Math.Sin(o.Heading), l = o.Length / 2.0, w = o.Width / 2.0;
            var corners = new (double X, double Y)[4];
            (double u, double v)[] local = [(-l, -w), (l, -w), (l, w), (-l, w)];
            for (int k = 0; k < 4; k++)
            {
                corners[k] = (o.Center.X + (local[k].u * c) - (local[k].v * s), o.Center.Y + (local[k].u * s) + (local[k].v * c));
            }

            bodies.Add(Truth.Polygon(SensedBody.Obstacle(o.Index), [corners]));
        }

        foreach (var b in snapshot.Balls)
        {
            bodies.Add(Truth.Disc(SensedBody.Ball(b.Index), b.Position, b.Radius));
        }

        foreach (var f in snapshot.Fish)
        {
            // The fish's shape is the collision model's leaves at the view's pose (the model is tested
            // against the original's geometry elsewhere); the queries on it are what is tested here.
            var model = new FishModel(new FishSize(f.BodyLength, f.Width, f.HeadLength, f.TailLength1, f.TailLength2, f.TailLength3), new FishPose(f.Position, f.Heading, f.Joint1, f.Joint2, f.Joint3));
            var leaves = new List<(double X, double Y)[]>();
            foreach (var part in Enum.GetValues<FishPart>())
            {
                var leaf = model.GetLeaf(part);
                var poly = new (double X, double Y)[leaf.Length];
                for (int k = 0; k < leaf.Length; k++)
                {
                    poly[k] = (leaf[k].X, leaf[k].Y);
                }

                leaves.Add(poly);
            }

            bodies.Add(Truth.Polygon(SensedBody.Fish(f.Index), leaves));
        }

        return bodies;
    }

    /// <summary>A point of the field no body contains (nor comes within <paramref name="margin"/> mm of).</summary>
    public (double X, double Y) FreePoint(Random rng, double margin = 1.0)
    {
        while (true)
        {
            var p = ((double)Point(rng, 1480f).X, (double)Point(rng, 980f).Y);
            if (Bodies.TrueForAll(b => b.Distance(p) > margin))
            {
                return p;
            }
        }
    }

    public static Vector2 Point(Random rng, float half) => new((rng.NextSingle() * 2f - 1f) * half, (rng.NextSingle() * 2f - 1f) * half * 0.9f);

    private static float Angle(Random rng) => (rng.NextSingle() * 2f - 1f) * MathF.PI;

    private static float Joint(Random rng) => (rng.NextSingle() * 2f - 1f) * 0.5f;
}
