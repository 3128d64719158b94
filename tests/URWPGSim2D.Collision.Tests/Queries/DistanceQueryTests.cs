namespace URWPGSim2D.Collision.Tests.Queries;

/// <summary>
/// <see cref="ShapeQuery.Distance(in Shape, in Shape)"/> against the double-precision reference gap
/// (Minkowski difference), dense boundary samples, circles' closed form, and the fish's leaves.
/// </summary>
public sealed class DistanceQueryTests
{
    private const double Tolerance = Tolerances.Depth;

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void DistanceAndPointsMatchTheReferenceGap(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var c in PairCorpus.For(kindA, kindB).Take(600))
        {
            double gap = QueryReference.Gap(c.A.Reference, c.B.Reference);
            if (Math.Abs(gap) <= Tolerances.TouchingBand)
            {
                continue;
            }

            log.Case();
            var r = ShapeQuery.Distance(c.A.Shape, c.B.Shape);
            Point2 pa = Point2.From(r.PointA), pb = Point2.From(r.PointB);
            if (gap > 0)
            {
                log.Check(Math.Abs(r.Distance - gap) <= Tolerance, $"{c}: distance {r.Distance} but the reference gap is {gap:R}");
                log.Check(Math.Abs(c.A.Reference.SignedDistance(pa)) <= Tolerance, $"{c}: pointA {pa} is not on a ({c.A.Reference.SignedDistance(pa):R})");
                log.Check(Math.Abs(c.B.Reference.SignedDistance(pb)) <= Tolerance, $"{c}: pointB {pb} is not on b ({c.B.Reference.SignedDistance(pb):R})");
                log.Check(Math.Abs(Point2.Distance(pa, pb) - gap) <= Tolerance, $"{c}: |pointA − pointB| = {Point2.Distance(pa, pb):R}, gap {gap:R}");
            }
            else
            {
                log.Check(r.Distance == 0f && r.PointA == r.PointB, $"{c}: overlapping (depth {-gap:R}) but {r}");
                log.Check(c.A.Reference.SignedDistance(pa) <= Tolerance && c.B.Reference.SignedDistance(pa) <= Tolerance, $"{c}: the contact point {pa} is not in both shapes");
            }
        }

        log.AssertNone(200);
    }

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void DistanceAgreesWithDenseBoundarySamples(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var c in PairCorpus.For(kindA, kindB).Where(c => c.Reference.SignedDepth < -Tolerances.TouchingBand).Take(25))
        {
            log.Case();
            var sa = QueryReference.BoundarySamples(c.A.Reference, 240);
            var sb = QueryReference.BoundarySamples(c.B.Reference, 240);
            double sampled = QueryReference.SampledDistance(sa, sb);
            double spacing = QueryReference.Spacing(sa) + QueryReference.Spacing(sb);
            float d = ShapeQuery.Distance(c.A.Shape, c.B.Shape).Distance;

            // Samples never come closer than the true distance, and miss it by at most the spacing.
            log.Check(d <= sampled + Tolerance, $"{c}: distance {d} exceeds the sampled {sampled:R}");
            log.Check(d >= sampled - spacing - Tolerance, $"{c}: distance {d} is below the sampled {sampled:R} less the spacing {spacing:R}");
        }

        log.AssertNone(10);
    }

    [Fact]
    public void CircleDistanceIsTheClosedForm()
    {
        var rng = new Random(27);
        for (int i = 0; i < 2000; i++)
        {
            var a = new Circle(FishTestKit.Point(rng, 5000f), FishTestKit.Range(rng, 1f, 300f));
            var b = new Circle(FishTestKit.Point(rng, 5000f), FishTestKit.Range(rng, 1f, 300f));
            double between = Point2.Distance(Point2.From(a.Center), Point2.From(b.Center));
            double expected = Math.Max(0, between - a.Radius - b.Radius);
            var r = ShapeQuery.Distance(a, b);
            Assert.True(Math.Abs(r.Distance - expected) <= 1e-3 + (1e-6 * between), $"{i}: {r.Distance} vs {expected}");
            if (expected > 1e-3)
            {
                Point2 u = (Point2.From(b.Center) - Point2.From(a.Center)) / between;
                Point2 onA = Point2.From(a.Center) + (u * a.Radius);
                Assert.True(Point2.Distance(Point2.From(r.PointA), onA) <= 1e-3, $"{i}: pointA {r.PointA} vs {onA}");
            }
        }
    }

    [Fact]
    public void PointDistanceIsTheSignedDistanceClampedAtZero()
    {
        var log = new FailureLog();
        foreach (var kind in Enum.GetValues<ShapeKind>())
        {
            var rng = new Random(100 + (int)kind);
            foreach (var c in PairCorpus.For(kind, kind).Take(150))
            {
                Point2 centre = c.A.Reference.Centre;
                double reach = c.A.Reference.BoundingRadius * 2;
                var p = new Vector2((float)(centre.X + ((rng.NextDouble() - 0.5) * reach)), (float)(centre.Y + ((rng.NextDouble() - 0.5) * reach)));
                double expected = Math.Max(0, c.A.Reference.SignedDistance(Point2.From(p)));
                log.Case();
                var r = ShapeQuery.Distance(c.A.Shape, p);
                log.Check(Math.Abs(r.Distance - expected) <= Tolerance, $"{c.A} to {p}: {r.Distance} vs {expected:R}");
            }
        }

        log.AssertNone(700);
    }

    [Fact]
    public void FishDistanceIsTheNearestLeafForEveryPartnerKind()
    {
        var rng = new Random(2727);
        var log = new FailureLog();
        for (int i = 0; i < 300; i++)
        {
            var fish = new FishModel(FishTestKit.Size(rng), FishTestKit.Pose(rng, spread: 100f));
            var leaves = QueryReference.Leaves(fish);
            Shape partner = (i % 5) switch
            {
                0 => FishTestKit.Circle(rng, 400f),
                1 => FishTestKit.Aabb(rng, 400f),
                2 => FishTestKit.KDop(rng, 400f),
                3 => FishTestKit.Polygon(rng, 400f),
                _ => new Segment(FishTestKit.Point(rng, 400f), FishTestKit.Point(rng, 400f)),
            };
            var partnerRef = ReferenceOf(partner);
            double gap = leaves.Min(l => QueryReference.Gap(l, partnerRef));
            if (Math.Abs(gap) <= Tolerances.TouchingBand)
            {
                continue;
            }

            log.Case();
            var r = ShapeQuery.Distance(fish, partner);
            log.Check(Math.Abs(r.Distance - Math.Max(0, gap)) <= Tolerance, $"{i}: fish–{partner.Kind} distance {r.Distance}, reference {gap:R}");
            if (gap > 0)
            {
                var leaf = leaves[(int)r.PartA!.Value];
                log.Check(Math.Abs(leaf.SignedDistance(Point2.From(r.PointA))) <= Tolerance, $"{i}: pointA is not on the reported leaf {r.PartA}");
                var swapped = ShapeQuery.Distance(partner, fish);
                log.Check(Math.Abs(swapped.Distance - r.Distance) <= 1e-4 && swapped.PartB == r.PartA, $"{i}: swapped {swapped} vs {r}");
            }
            else
            {
                log.Check(r.PartA is not null && leaves.Min(l => l.SignedDistance(Point2.From(r.PointA))) <= Tolerance, $"{i}: the contact point is not in the fish");
            }
        }

        log.AssertNone(200);
    }

    [Fact]
    public void FishToFishDistanceIsTheNearestPairOfLeaves()
    {
        var rng = new Random(99);
        var log = new FailureLog();
        for (int i = 0; i < 150; i++)
        {
            var a = new FishModel(FishTestKit.Size(rng), FishTestKit.Pose(rng, spread: 300f));
            var b = new FishModel(FishTestKit.Size(rng), FishTestKit.Pose(rng, spread: 300f));
            double gap = QueryReference.Gap(QueryReference.Leaves(a), QueryReference.Leaves(b));
            if (Math.Abs(gap) <= Tolerances.TouchingBand)
            {
                continue;
            }

            log.Case();
            var r = ShapeQuery.Distance(a, b);
            log.Check(Math.Abs(r.Distance - Math.Max(0, gap)) <= Tolerance, $"{i}: {r.Distance} vs {gap:R}");
            log.Check(r.PartA is not null && r.PartB is not null, $"{i}: parts missing in {r}");
        }

        log.AssertNone(100);
    }

    internal static ReferenceShape ReferenceOf(Shape s) => s.Kind switch
    {
        ShapeKind.Circle => ReferenceShape.Circle(s.AsCircle().Center, s.AsCircle().Radius),
        ShapeKind.Aabb => ReferenceShape.Aabb(s.AsAabb().Min, s.AsAabb().Max),
        ShapeKind.KDop8 => ReferenceShape.KDop8(
            Enumerable.Range(0, 4).Select(i => (double)s.AsKDop8().GetMin(i)).ToArray(),
            Enumerable.Range(0, 4).Select(i => (double)s.AsKDop8().GetMax(i)).ToArray()),
        ShapeKind.Polygon => ReferenceShape.Polygon(s.AsPolygon().Vertices.ToArray()),
        _ => ReferenceShape.Segment(s.AsSegment().A, s.AsSegment().B),
    };
}
