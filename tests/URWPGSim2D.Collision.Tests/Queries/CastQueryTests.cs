namespace URWPGSim2D.Collision.Tests.Queries;

/// <summary>
/// <see cref="ShapeQuery.Cast(in Shape, Vector2, in Shape)"/> against the first root, in double,
/// of the reference signed gap of the moving shape (translated exactly) and the other one.
/// </summary>
public sealed class CastQueryTests
{
    private const double Tolerance = Tolerances.Depth;

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void FirstContactMatchesTheReferenceRoot(ShapeKind kindA, ShapeKind kindB)
    {
        var rng = new Random((10 * (int)kindA) + (int)kindB);
        var log = new FailureLog();
        int hits = 0;
        foreach (var c in PairCorpus.For(kindA, kindB).Where(c => c.Reference.SignedDepth < -0.1).Take(120))
        {
            Point2 toward = c.B.Reference.Centre - c.A.Reference.Centre;
            Point2 jitter = Point2.FromAngle(rng.NextDouble() * 2 * Math.PI) * (toward.Length * 0.6 * rng.NextDouble());
            Vector2 translation = ((toward * (0.3 + (1.5 * rng.NextDouble()))) + jitter).ToVector2();
            Point2 move = Point2.From(translation);
            double length = move.Length;
            Func<double, double> gap = t => QueryReference.Gap(c.A.Reference.Translated(move * t), c.B.Reference);
            double? root = QueryReference.FirstRoot(gap);
            if (Math.Abs(gap(1)) <= Tolerance || MinimumNear(gap, length))
            {
                continue;
            }

            log.Case();
            var r = ShapeQuery.Cast(c.A.Shape, translation, c.B.Shape);
            log.Check(r.Hit == (root is not null), $"{c}: translation {translation}: hit {r.Hit}, reference {root?.ToString("R") ?? "miss"}");
            if (!r.Hit || root is null)
            {
                continue;
            }

            hits++;
            // Never past the contact, and short of it by at most the cast tolerance.
            double at = gap(r.Fraction);
            log.Check(at >= -Tolerance && at <= ShapeQuery.CastTolerance + Tolerance, $"{c}: translation {translation}: gap {at:R} at the reported fraction {r.Fraction} (reference {root:R})");
            log.Check(Math.Abs(r.Fraction - root.Value) * length <= (ShapeQuery.CastTolerance + Tolerance) * 50, $"{c}: fraction {r.Fraction}, reference {root:R}");
            Point2 p = Point2.From(r.Point);
            log.Check(Math.Abs(c.B.Reference.SignedDistance(p)) <= Tolerance, $"{c}: the point {p} is not on b");
            log.Check(Point2.Dot(Point2.From(r.Normal), move) <= 1e-6 * length, $"{c}: the normal {r.Normal} does not face the motion {translation}");
        }

        log.AssertNone(30);
        Assert.True(hits > 5, $"only {hits} hits");
    }

    [Fact]
    public void CirclesMeetAtTheClosedFormTime()
    {
        var rng = new Random(8);
        int hits = 0;
        for (int i = 0; i < 1000; i++)
        {
            var a = new Circle(FishTestKit.Point(rng, 500f), FishTestKit.Range(rng, 5f, 100f));
            var b = new Circle(FishTestKit.Point(rng, 500f), FishTestKit.Range(rng, 5f, 100f));
            Vector2 translation = ((b.Center - a.Center) * FishTestKit.Range(rng, 0.3f, 2f)) + FishTestKit.Point(rng, 150f);
            Point2 s = Point2.From(a.Center) - Point2.From(b.Center), d = Point2.From(translation);
            double r = (double)a.Radius + b.Radius;
            double qa = Point2.Dot(d, d), qb = Point2.Dot(s, d), qc = Point2.Dot(s, s) - (r * r);
            double disc = (qb * qb) - (qa * qc);
            if (qc <= 1 || Math.Abs(disc) < 1e-2 * qa * qa)
            {
                continue;
            }

            double t = disc > 0 ? (-qb - Math.Sqrt(disc)) / qa : double.NaN;
            bool expected = disc > 0 && t >= 0 && t <= 1;
            if (disc > 0 && (Math.Abs(t - 1) * Math.Sqrt(qa) < 0.01))
            {
                continue;
            }

            var result = ShapeQuery.Cast(a, translation, b);
            Assert.True(result.Hit == expected, $"{i}: hit {result.Hit} vs {expected} (t {t})");
            if (expected)
            {
                hits++;
                Assert.True(Math.Abs(result.Fraction - t) * Math.Sqrt(qa) <= 0.02, $"{i}: {result.Fraction} vs {t}");
            }
        }

        Assert.True(hits > 50, $"only {hits} hits");
    }

    [Fact]
    public void OverlappingAtTheStartIsFractionZeroWithTheNarrowPhaseContact()
    {
        Shape a = new Aabb(new Vector2(0f, 0f), new Vector2(10f, 10f));
        Shape b = new Circle(new Vector2(12f, 5f), 4f);
        var r = ShapeQuery.Cast(a, new Vector2(-100f, 0f), b);
        var contact = CollisionDetector.Detect(a, b);
        Assert.True(r.Hit);
        Assert.Equal(0f, r.Fraction);
        Assert.Equal(contact.ActionPoint.X, r.Point.X);
        Assert.Equal(contact.NormalAxis.X, r.Normal.X);
    }

    [Fact]
    public void FishCastMatchesTheReferenceOverLeaves()
    {
        var rng = new Random(31);
        var log = new FailureLog();
        int hits = 0;
        for (int i = 0; i < 120; i++)
        {
            var fish = new FishModel(FishTestKit.Size(rng), FishTestKit.Pose(rng, spread: 30f));
            var leaves = QueryReference.Leaves(fish);
            Shape other = (i % 3) switch
            {
                0 => FishTestKit.Circle(rng, 50f).Translated(new Vector2(400f, 0f)),
                1 => FishTestKit.Polygon(rng, 50f).Translated(new Vector2(400f, 0f)),
                _ => FishTestKit.Aabb(rng, 50f).Translated(new Vector2(400f, 0f)),
            };
            var otherRef = DistanceQueryTests.ReferenceOf(other);
            Vector2 translation = new(FishTestKit.Range(rng, 200f, 900f), FishTestKit.Range(rng, -300f, 300f));
            Point2 move = Point2.From(translation);
            Func<double, double> gap = t => leaves.Min(l => QueryReference.Gap(l.Translated(move * t), otherRef));

            // Each leaf's gap is convex along the move (the fish's, a minimum of them, is not): root per leaf.
            var perLeaf = leaves.Select(l => (Func<double, double>)(t => QueryReference.Gap(l.Translated(move * t), otherRef))).ToArray();
            if (gap(0) <= 0.1 || Math.Abs(gap(1)) <= Tolerance || perLeaf.Any(f => MinimumNear(f, move.Length)))
            {
                continue;
            }

            double? root = perLeaf.Select(f => QueryReference.FirstRoot(f)).Where(x => x is not null).DefaultIfEmpty(null).Min();
            log.Case();
            var r = ShapeQuery.Cast(fish, translation, other);
            log.Check(r.Hit == (root is not null), $"{i}: hit {r.Hit} at {r.Fraction} (gap there {gap(r.Fraction):R}, {r.PartA}), reference {root}");
            if (r.Hit && root is not null)
            {
                hits++;
                double at = gap(r.Fraction);
                log.Check(at >= -Tolerance && at <= ShapeQuery.CastTolerance + Tolerance, $"{i}: gap {at:R} at {r.Fraction} (reference {root:R})");
                log.Check(r.PartA is not null, $"{i}: no part");
            }
        }

        log.AssertNone(60);
        Assert.True(hits > 10, $"only {hits} hits");
    }

    // The gap's minimum along the move is within the tolerance of 0: a graze, either answer is right.
    private static bool MinimumNear(Func<double, double> f, double length)
    {
        double lo = 0, hi = 1;
        for (int i = 0; i < 100; i++)
        {
            double m1 = lo + ((hi - lo) / 3), m2 = hi - ((hi - lo) / 3);
            if (f(m1) <= f(m2))
            {
                hi = m2;
            }
            else
            {
                lo = m1;
            }
        }

        return Math.Abs(f((lo + hi) / 2)) <= (2 * Tolerance) + (1e-6 * length);
    }
}
