namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// Every ordered pair of kinds, 2,000 random pairs each, against the brute-force double-precision
/// reference (distance from the origin to the boundary of the Minkowski difference).
/// </summary>
public sealed class ReferenceAgreementTests
{
    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void IntersectAgreesWithTheReferenceOutsideTheTouchingBand(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var c in PairCorpus.For(kindA, kindB))
        {
            if (!c.Decided)
            {
                continue;
            }

            log.Case();
            var r = CollisionDetector.Detect(c.A.Shape, c.B.Shape);
            log.Check(r.Intersect == c.Reference.Intersect, $"{c}: library {r}");
        }

        log.AssertNone(PairCorpus.CasesPerPair * 3 / 4);
    }

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void DepthAgreesWithTheReferenceWithinTheAccuracyGoal(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var (c, r) in PairCorpus.Overlapping(kindA, kindB, referenceToo: true))
        {
            log.Case();
            double error = r.Depth - c.Reference.SignedDepth;
            log.Check(Math.Abs(error) <= Tolerances.Depth, $"{c}: library depth {r.Depth:R} (error {error:R})");
        }

        log.AssertNone(PairCorpus.CasesPerPair / 4);
    }

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void NormalIsTheUnitMtvDirectionAndAMinimalDirection(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var (c, r) in PairCorpus.Overlapping(kindA, kindB, referenceToo: true))
        {
            log.Case();
            Point2 n = Point2.FromWorld(r.NormalAxis);
            Point2 mtv = Point2.FromWorld(r.MinimumTranslationVector);
            log.Check(r.NormalAxis.Y == 0 && r.MinimumTranslationVector.Y == 0 && r.ActionPoint.Y == 0, $"{c}: Y not 0 in {r}");
            log.Check(Math.Abs(n.Length - 1) <= Tolerances.UnitLength, $"{c}: |normal| = {n.Length:R}");
            log.Check(Point2.Distance(mtv, n * r.Depth) <= 1e-6 * (1 + r.Depth), $"{c}: MTV {mtv} is not normal·depth");

            // Translating a along the library's normal needs exactly the minimal depth.
            double along = ReferenceGeometry.DirectionalDepth(c.A.Reference, c.B.Reference, n);
            log.Check(along <= c.Reference.SignedDepth + Tolerances.Depth, $"{c}: along normal {n} a must move {along:R} mm, the minimum is {c.Reference.SignedDepth:R}");
        }

        log.AssertNone(PairCorpus.CasesPerPair / 4);
    }

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void NoOverlapGivesAnAllZeroResult(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var c in PairCorpus.For(kindA, kindB))
        {
            var r = CollisionDetector.Detect(c.A.Shape, c.B.Shape);
            if (r.Intersect)
            {
                continue;
            }

            log.Case();
            log.Check(r == CollisionDetectionResult.None && r.Depth == 0, $"{c}: not all zero: {r.MinimumTranslationVector} {r.NormalAxis} {r.ActionPoint}");
        }

        log.AssertNone(PairCorpus.CasesPerPair / 10);
    }
}
