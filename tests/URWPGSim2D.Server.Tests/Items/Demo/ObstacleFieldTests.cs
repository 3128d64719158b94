using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Server.Tests.Items.Demo;

/// <summary>
/// The demo strategies' view of borders and obstacles (<see cref="ObstacleField"/>), against
/// brute force: outlines sampled every 0.05 mm, segments sampled every 0.5 mm.
/// </summary>
public sealed class ObstacleFieldTests
{
    private const float Length = 3000f, Width = 2000f;

    // An axis-aligned bar, a rotated rectangle, a disc.
    private static readonly ObstacleView[] Obstacles =
    [
        new(0, ObstacleKind.Rectangle, new Vector2(-900f, 300f), 400f, 60f, 0f, 0f),
        new(1, ObstacleKind.Rectangle, new Vector2(400f, -250f), 500f, 200f, 0.6f, 0f),
        new(2, ObstacleKind.Round, new Vector2(800f, 500f), 0f, 0f, 0f, 150f),
    ];

    private static ObstacleField Field() => new(new MatchSnapshot(0, 0, Obstacles, Length, Width));

    [Fact]
    public void TheMeasuredClearanceIsTheSignedDistanceToTheNearestOutline()
    {
        var field = Field();
        var rng = new Random(3);
        for (int i = 0; i < 400; i++)
        {
            Vector2 p = RandomPoint(rng, 1.05f);
            float truth = BruteClearance(p);
            Assert.True(MathF.Abs(field.Measure(p) - truth) <= 0.06f, $"case {i}: at {p} measured {field.Measure(p)}, brute force {truth}");
        }
    }

    [Fact]
    public void TheGridClearanceIsExactAtGridPointsAndWithinItsToleranceBetween()
    {
        var field = Field();
        var rng = new Random(4);
        float high = 0f, low = 0f, near = 0f;
        for (int i = 0; i < 20000; i++)
        {
            Vector2 grid = new((rng.Next(0, 151) * ObstacleField.Cell) - (Length / 2f), (rng.Next(0, 101) * ObstacleField.Cell) - (Width / 2f));
            Assert.Equal(field.Measure(grid), field.Clearance(grid), 3);

            Vector2 p = RandomPoint(rng, 1.1f);
            float exact = field.Measure(p), looked = field.Clearance(p);
            high = MathF.Max(high, exact >= 100f ? looked - exact : 0f);
            low = MathF.Max(low, exact - looked);
            near = MathF.Max(near, exact < 100f ? looked - exact : 0f);
        }

        // Above the truth by under 1 mm where the clearance is 100 mm or more (the curvature of a
        // distance within a cell), by up to half a cell close to a corner; below it by up to half a
        // cell where two nearest features meet (a kink the interpolation cuts across).
        Assert.True(high <= 1f, $"reads {high} mm high at 100 mm or more");
        Assert.True(near <= ObstacleField.Cell / 2f, $"reads {near} mm high under 100 mm");
        Assert.True(low <= ObstacleField.Cell / 2f, $"reads {low} mm low");
    }

    [Fact]
    public void TheClearanceChangesNoFasterThanItsStatedSlope()
    {
        // The demos skip path samples on this bound. Besides the usual field: obstacles that overlap
        // each other and cross the border, where the signed clearance has its kinks.
        var crossing = new ObstacleField(new MatchSnapshot(0, 0,
        [
            new(0, ObstacleKind.Rectangle, new Vector2(-1450f, 0f), 300f, 400f, 0.3f, 0f),
            new(1, ObstacleKind.Round, new Vector2(-1300f, 150f), 0f, 0f, 0f, 200f),
            new(2, ObstacleKind.Rectangle, new Vector2(600f, 980f), 800f, 120f, 0f, 0f),
        ], Length, Width));
        var rng = new Random(6);
        foreach (var field in new[] { Field(), crossing })
        {
            float inField = 0f, anywhere = 0f;
            for (int i = 0; i < 40000; i++)
            {
                Vector2 a = RandomPoint(rng, 1.1f);
                Vector2 b = a + (new Vector2(rng.NextSingle() - 0.5f, rng.NextSingle() - 0.5f) * 160f);
                float slope = MathF.Abs(field.Clearance(a) - field.Clearance(b)) / MathF.Max(Vector2.Distance(a, b), 1e-3f);
                bool inside = MathF.Abs(a.X) <= Length / 2f && MathF.Abs(b.X) <= Length / 2f && MathF.Abs(a.Y) <= Width / 2f && MathF.Abs(b.Y) <= Width / 2f;
                inField = inside ? MathF.Max(inField, slope) : inField;
                anywhere = MathF.Max(anywhere, slope);
            }

            Assert.True(inField <= MathF.Sqrt(2f) + 0.01f, $"{inField} mm a mm in the field");
            Assert.True(anywhere <= ObstacleField.MaxSlope, $"{anywhere} mm a mm");
            Assert.True(inField >= 0.9f, $"the steepest change seen is only {inField}: the test samples too little");
        }
    }

    [Fact]
    public void ASegmentIsBlockedExactlyWhenItPassesThroughAGrownBoundingBox()
    {
        var field = Field();
        var rng = new Random(5);
        int blocked = 0, free = 0;
        for (int i = 0; i < 600; i++)
        {
            Vector2 a = RandomPoint(rng, 1f), b = rng.Next(4) == 0 ? a + new Vector2(rng.NextSingle() * 300f, 0f) : RandomPoint(rng, 1f);
            float margin = rng.NextSingle() * 150f;
            int first = field.FirstBlocking(a, b, margin);
            int truth = -1;
            bool grazing = false;
            for (int o = 0; o < field.Count && truth < 0; o++)
            {
                var box = field.Bounds(o);
                Vector2 min = box.Min - new Vector2(margin), max = box.Max + new Vector2(margin);
                int steps = (int)(Vector2.Distance(a, b) / 0.5f) + 1;
                for (int k = 0; k <= steps; k++)
                {
                    Vector2 p = Vector2.Lerp(a, b, k / (float)steps);
                    float depth = MathF.Min(MathF.Min(p.X - min.X, max.X - p.X), MathF.Min(p.Y - min.Y, max.Y - p.Y));
                    if (depth > 0.5f)
                    {
                        truth = o;
                        break;
                    }

                    grazing |= depth > -0.5f;
                }
            }

            if (truth < 0 && grazing)
            {
                continue; // within the sampling's resolution of the grown box: either answer is right
            }

            Assert.True(first == truth, $"case {i}: {a} → {b}, margin {margin}: first blocking {first}, brute force {truth}");
            _ = truth >= 0 ? blocked++ : free++;
        }

        Assert.True(blocked > 100 && free > 100, $"cases: {blocked} blocked, {free} free");
    }

    [Fact]
    public void LookingUpAllocatesNothing()
    {
        var field = Field();
        var rng = new Random(6);
        var points = Enumerable.Range(0, 256).Select(_ => RandomPoint(rng, 1f)).ToArray();
        float sum = 0f;
        foreach (var p in points)
        {
            sum += field.Clearance(p) + field.FirstBlocking(p, -p, 100f);
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        foreach (var p in points)
        {
            sum += field.Clearance(p) + field.FirstBlocking(p, -p, 100f);
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        Assert.True(float.IsFinite(sum));
    }

    private static Vector2 RandomPoint(Random rng, float spread) =>
        new((rng.NextSingle() - 0.5f) * Length * spread, (rng.NextSingle() - 0.5f) * Width * spread);

    // The signed distance to the nearest border or obstacle by sampling every outline densely.
    private static float BruteClearance(Vector2 p)
    {
        Vector2 half = new(Length / 2f, Width / 2f);
        Vector2 beyond = Vector2.Max(Vector2.Abs(p) - half, Vector2.Zero);
        float best = beyond == Vector2.Zero ? MathF.Min(half.X - MathF.Abs(p.X), half.Y - MathF.Abs(p.Y)) : -beyond.Length();
        foreach (var o in Obstacles)
        {
            Vector2[] outline = Outline(o);
            float d = float.PositiveInfinity;
            foreach (var q in outline)
            {
                d = MathF.Min(d, Vector2.Distance(p, q));
            }

            best = MathF.Min(best, Inside(o, p) ? -d : d);
        }

        return best;
    }

    private static Vector2[] Outline(ObstacleView o)
    {
        if (o.Kind == ObstacleKind.Round)
        {
            int n = (int)(2f * MathF.PI * o.Radius / 0.05f);
            return [.. Enumerable.Range(0, n).Select(k => o.Center + (o.Radius * new Vector2(MathF.Cos(k * 2f * MathF.PI / n), MathF.Sin(k * 2f * MathF.PI / n))))];
        }

        Vector2 u = new(MathF.Cos(o.Heading), MathF.Sin(o.Heading)), v = new(-u.Y, u.X);
        Vector2[] corners =
        [
            o.Center - (u * o.Length / 2f) - (v * o.Width / 2f), o.Center + (u * o.Length / 2f) - (v * o.Width / 2f),
            o.Center + (u * o.Length / 2f) + (v * o.Width / 2f), o.Center - (u * o.Length / 2f) + (v * o.Width / 2f),
        ];
        return [.. Enumerable.Range(0, 4).SelectMany(e =>
        {
            Vector2 a = corners[e], b = corners[(e + 1) % 4];
            int n = (int)(Vector2.Distance(a, b) / 0.05f) + 1;
            return Enumerable.Range(0, n + 1).Select(k => Vector2.Lerp(a, b, k / (float)n));
        })];
    }

    private static bool Inside(ObstacleView o, Vector2 p)
    {
        if (o.Kind == ObstacleKind.Round)
        {
            return Vector2.Distance(p, o.Center) < o.Radius;
        }

        Vector2 d = p - o.Center, u = new(MathF.Cos(o.Heading), MathF.Sin(o.Heading));
        return MathF.Abs(Vector2.Dot(d, u)) < o.Length / 2f && MathF.Abs((d.X * -u.Y) + (d.Y * u.X)) < o.Width / 2f;
    }
}
