namespace URWPGSim2D.Strategies.Tests.Sensing;

/// <summary>
/// <see cref="FieldSensor"/>'s answers on random scenes against the double-precision truth of
/// <see cref="Truth"/>: a point's distance to a polygon (obstacles and the fish's leaves) by brute force
/// over boundary samples 0.25 mm apart, the gap between two bodies exact (edge against edge, centre
/// against edge for a disc), analytic for discs and borders.
/// </summary>
public sealed class FieldSensorPropertyTests
{
    // The brute force's spacing error (half a sample step) plus float round-off of coordinates up to 1,500 mm.
    private const double Tolerance = (0.5 / SensedScene.SamplesPerMm) + 2e-3;

    [Fact]
    public void NearestAndClearanceMatchBruteForce()
    {
        var rng = new Random(2701);
        var sensor = new FieldSensor();
        for (int scene = 0; scene < 12; scene++)
        {
            var s = SensedScene.Random(rng);
            sensor.Observe(s.Snapshot);
            for (int k = 0; k < 25; k++)
            {
                var p = (k % 5 == 0) ? s.FreePoint(rng, 0) : ((double)SensedScene.Point(rng, 1500f).X, (double)SensedScene.Point(rng, 1000f).Y);
                var point = new Vector2((float)p.Item1, (float)p.Item2);
                var near = sensor.Nearest(point);
                double truth = s.Bodies.Min(b => b.Distance(p));
                Assert.True(Math.Abs(near.Distance - truth) <= Tolerance, $"scene {scene}: nearest to {point} is {near}, brute force {truth:R}");
                Assert.True(Math.Abs(s.Bodies.Single(b => b.Body == near.Body).Distance(p) - truth) <= 2 * Tolerance, $"scene {scene}: {near.Body} is not a nearest body to {point}");
                double staticTruth = s.Bodies.Where(b => b.Body.Kind is SensedKind.Wall or SensedKind.Obstacle).Min(b => b.Distance(p));
                Assert.True(Math.Abs(sensor.Clearance(point) - staticTruth) <= Tolerance, $"scene {scene}: clearance at {point} {sensor.Clearance(point)}, brute force {staticTruth:R}");
                foreach (var b in s.Bodies)
                {
                    var d = sensor.Distance(b.Body, point);
                    Assert.True(Math.Abs(d.Distance - b.Distance(p)) <= Tolerance, $"scene {scene}: {b.Body} to {point}: {d}, brute force {b.Distance(p):R}");
                    if (d.Distance > 0)
                    {
                        // The nearest point lies on the body's boundary, at the distance reported.
                        Assert.True(b.BoundaryDistance((d.PointA.X, d.PointA.Y)) <= Tolerance, $"{b.Body}: {d.PointA} is off its boundary");
                        Assert.True(Math.Abs(Vector2.Distance(d.PointA, point) - d.Distance) <= 1e-2, $"{b.Body}: {d}");
                    }
                }
            }
        }
    }

    [Fact]
    public void RayEntersWhereTheSampledRayFirstEntersABody()
    {
        var rng = new Random(2702);
        var sensor = new FieldSensor();
        int hits = 0, cases = 0, grazing = 0;
        for (int scene = 0; scene < 12; scene++)
        {
            var s = SensedScene.Random(rng);
            sensor.Observe(s.Snapshot);
            for (int k = 0; k < 20; k++)
            {
                var a = s.FreePoint(rng);
                var b = ((double)SensedScene.Point(rng, 1700f).X, (double)SensedScene.Point(rng, 1200f).Y);
                Vector2 from = new((float)a.X, (float)a.Y), to = new((float)b.Item1, (float)b.Item2);
                var hit = sensor.RayCast(from, to);
                double length = Vector2.Distance(from, to);

                // The first sample of the ray (0.25 mm apart) inside any body, refined by bisection.
                double? first = FirstInside(s, from, to, length);
                cases++;
                if (!hit.Hit)
                {
                    Assert.True(first is null, $"scene {scene}: ray {from}→{to} misses, but the point at {first:R} is inside a body");
                    continue;
                }

                hits++;
                grazing += first is null ? 1 : 0; // entered between two samples and left again: a corner grazed
                if (first is { } t)
                {
                    Assert.True(hit.Result.Fraction * length <= (t * length) + Tolerance, $"scene {scene}: ray {from}→{to} enters {hit.Body} at {hit.Result.Fraction:R}, a body already at {t:R}");
                }

                var truth = s.Bodies.Single(x => x.Body == hit.Body);
                var point = (hit.Result.Point.X, hit.Result.Point.Y);
                Assert.True(truth.BoundaryDistance(point) <= Tolerance, $"scene {scene}: {hit} is not on the boundary of {hit.Body}");
                Assert.True(Vector2.Distance(hit.Result.Point, from + (hit.Result.Fraction * (to - from))) <= 1e-2);
                Assert.True(Vector2.Dot(hit.Result.Normal, to - from) <= 0f, $"scene {scene}: normal {hit.Result.Normal} does not face the ray's start");
                Assert.Equal(hit.Body.Kind == SensedKind.Fish, hit.Result.Part is not null);
            }
        }

        Assert.True(hits > cases / 2, $"only {hits} of {cases} rays hit: the scenes test too little");
        Assert.True(grazing <= hits / 20, $"{grazing} of {hits} hits have no sample inside a body");
    }

    [Fact]
    public void DistanceBetweenBodiesMatchesTheExactGap()
    {
        var rng = new Random(2703);
        var sensor = new FieldSensor();
        for (int scene = 0; scene < 24; scene++)
        {
            var s = SensedScene.Random(rng, fishCount: 3, ballCount: 2);
            sensor.Observe(s.Snapshot);
            var bodies = s.Bodies.Where(b => !b.IsBorder).ToList();
            for (int i = 0; i < bodies.Count; i++)
            {
                for (int j = i + 1; j < bodies.Count; j++)
                {
                    var d = sensor.Distance(bodies[i].Body, bodies[j].Body);
                    double truth = bodies[i].IsDisc && bodies[j].IsDisc ? AnalyticDiscGap(s, bodies[i].Body, bodies[j].Body) : Truth.Gap(bodies[i], bodies[j]);
                    Assert.True(Math.Abs(d.Distance - truth) <= 2 * Tolerance, $"scene {scene}: {bodies[i].Body} to {bodies[j].Body}: {d}, exact {truth:R}");
                    var swapped = sensor.Distance(bodies[j].Body, bodies[i].Body);
                    Assert.True(Math.Abs(swapped.Distance - d.Distance) <= 1e-3, $"{bodies[i].Body}, {bodies[j].Body}: not symmetric: {d} and {swapped}");
                    if (d.Distance > 0)
                    {
                        Assert.True(bodies[i].BoundaryDistance((d.PointA.X, d.PointA.Y)) <= Tolerance, $"{d.PointA} is off {bodies[i].Body}");
                        Assert.True(bodies[j].BoundaryDistance((d.PointB.X, d.PointB.Y)) <= Tolerance, $"{d.PointB} is off {bodies[j].Body}");
                    }

                    Assert.Equal(bodies[i].Body.Kind == SensedKind.Fish, d.PartA is not null);
                    Assert.Equal(bodies[j].Body.Kind == SensedKind.Fish, d.PartB is not null);
                }
            }
        }
    }

    [Fact]
    public void DistanceBetweenRectanglesAndDiscsIsTheHandComputedGap()
    {
        var snapshot = FieldSensorTests.Scene(
            balls:
            [
                new BallView(0, new Vector2(0f, 200f), Vector2.Zero, 30f),
                new BallView(1, new Vector2(300f, 200f), Vector2.Zero, 30f),
                new BallView(2, new Vector2(90f, 40f), Vector2.Zero, 20f),
                new BallView(3, new Vector2(0f, 0f), Vector2.Zero, 10f),
            ],
            obstacles:
            [
                new ObstacleView(0, ObstacleKind.Rectangle, Vector2.Zero, 200f, 100f, 0f, 0f),                  // x in ±100, y in ±50
                new ObstacleView(1, ObstacleKind.Rectangle, new Vector2(300f, 0f), 100f, 100f, MathF.PI / 4, 0f), // a diamond, corners 50√2 from (300, 0)
                new ObstacleView(2, ObstacleKind.Round, new Vector2(-400f, 0f), 0f, 0f, 0f, 50f),
                new ObstacleView(3, ObstacleKind.Rectangle, Vector2.Zero, 40f, 20f, 0.3f, 0f),                  // inside obstacle 0
                new ObstacleView(4, ObstacleKind.Rectangle, Vector2.Zero, 40f, 400f, 0f, 0f),                   // crosses obstacle 0, no corner inside it
                new ObstacleView(5, ObstacleKind.Rectangle, new Vector2(400f, -300f), 100f, 100f, 0f, 0f),      // corner (350, −250) facing obstacle 0's (100, −50)
            ]);
        var sensor = new FieldSensor();
        sensor.Observe(snapshot);
        var truth = SensedScene.TruthOf(snapshot);
        (SensedBody A, SensedBody B, double Gap)[] cases =
        [
            (SensedBody.Obstacle(0), SensedBody.Obstacle(1), 200 - (50 * Math.Sqrt(2))),
            (SensedBody.Obstacle(0), SensedBody.Obstacle(2), 250),
            (SensedBody.Obstacle(0), SensedBody.Ball(0), 120),
            (SensedBody.Obstacle(1), SensedBody.Ball(1), 170 - (50 * Math.Sqrt(2))),
            (SensedBody.Obstacle(0), SensedBody.Obstacle(5), Math.Sqrt((250 * 250) + (200 * 200))),
            (SensedBody.Obstacle(2), SensedBody.Ball(0), Math.Sqrt((400 * 400) + (200 * 200)) - 80),
            (SensedBody.Obstacle(0), SensedBody.Ball(2), 0),
            (SensedBody.Obstacle(0), SensedBody.Ball(3), 0),
            (SensedBody.Obstacle(0), SensedBody.Obstacle(3), 0),
            (SensedBody.Obstacle(0), SensedBody.Obstacle(4), 0),
        ];
        foreach (var (a, b, gap) in cases)
        {
            // The reference the random scenes use, and the sensor, both against the hand-computed gap.
            double reference = Truth.Gap(truth.Single(t => t.Body == a), truth.Single(t => t.Body == b));
            Assert.True(Math.Abs(reference - gap) <= 1e-3, $"{a} to {b}: the reference says {reference:R}, by hand {gap:R}");
            Assert.True(Math.Abs(sensor.Distance(a, b).Distance - gap) <= 2 * Tolerance, $"{a} to {b}: {sensor.Distance(a, b)}, by hand {gap:R}");
        }
    }

    [Fact]
    public void OverlapFindsEveryBodyWithinTheDisc()
    {
        var rng = new Random(2704);
        var sensor = new FieldSensor();
        Span<SensedBody> found = stackalloc SensedBody[32];
        int nonEmpty = 0;
        for (int scene = 0; scene < 12; scene++)
        {
            var s = SensedScene.Random(rng);
            sensor.Observe(s.Snapshot);
            for (int k = 0; k < 20; k++)
            {
                var p = s.FreePoint(rng, 0);
                float radius = 20f + (400f * rng.NextSingle());
                var centre = new Vector2((float)p.X, (float)p.Y);
                int n = sensor.Overlap(new URWPGSim2D.Collision.Shapes.Circle(centre, radius), found);

                // A body overlaps the disc's interior exactly when its distance to the centre is below the radius.
                var expected = s.Bodies.Where(b => b.Distance(p) < radius - Tolerance).Select(b => b.Body).ToList();
                var unsure = s.Bodies.Where(b => Math.Abs(b.Distance(p) - radius) <= Tolerance).Select(b => b.Body).ToList();
                var got = found[..n].ToArray();
                Assert.All(expected, b => Assert.Contains(b, got));
                Assert.All(got, b => Assert.True(expected.Contains(b) || unsure.Contains(b), $"scene {scene}: {b} reported overlapping the disc {centre} r {radius}"));
                nonEmpty += n > 0 ? 1 : 0;
            }
        }

        Assert.True(nonEmpty > 50, $"only {nonEmpty} discs overlap anything");
    }

    private static double AnalyticDiscGap(SensedScene s, SensedBody a, SensedBody b)
    {
        (Vector2 c, float r) Of(SensedBody x) => x.Kind == SensedKind.Ball
            ? (s.Snapshot.Balls[x.Index].Position, s.Snapshot.Balls[x.Index].Radius)
            : (s.Snapshot.Obstacles[x.Index].Center, s.Snapshot.Obstacles[x.Index].Radius);
        var (ca, ra) = Of(a);
        var (cb, rb) = Of(b);
        return Math.Max(0, Truth.Hypot((double)ca.X - cb.X, (double)ca.Y - cb.Y) - ra - rb);
    }

    private static double? FirstInside(SensedScene s, Vector2 from, Vector2 to, double length)
    {
        int steps = (int)Math.Ceiling(length * SensedScene.SamplesPerMm);
        (double X, double Y) At(double t) => (from.X + (t * (to.X - from.X)), from.Y + (t * (to.Y - from.Y)));
        bool Inside(double t) => s.Bodies.Any(b => b.Inside(At(t)));
        for (int i = 1; i <= steps; i++)
        {
            double t = (double)i / steps;
            if (!Inside(t))
            {
                continue;
            }

            double lo = (double)(i - 1) / steps, hi = t;
            for (int k = 0; k < 40; k++)
            {
                double mid = 0.5 * (lo + hi);
                if (Inside(mid))
                {
                    hi = mid;
                }
                else
                {
                    lo = mid;
                }
            }

            return hi;
        }

        return null;
    }
}
