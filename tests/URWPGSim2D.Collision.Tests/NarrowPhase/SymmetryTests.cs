namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>Swapping the shapes must not change the contact beyond its sign; translating both must not change the MTV.</summary>
public sealed class SymmetryTests
{
    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void SwappingTheShapesNegatesMtvAndNormalAndKeepsTheActionPoint(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var c in PairCorpus.For(kindA, kindB))
        {
            log.Case();
            var ab = CollisionDetector.Detect(c.A.Shape, c.B.Shape);
            var ba = CollisionDetector.Detect(c.B.Shape, c.A.Shape);
            string? why = ContactComparison.Difference(ab, ba.Swapped(), c);
            log.Check(why is null, $"{c}: {why}; a,b: {ab}; b,a: {ba}");
        }

        log.AssertNone(PairCorpus.CasesPerPair);
    }

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void TranslatingBothShapesTranslatesTheContact(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        var gen = new RandomShapes(101 * (5 * (int)kindA + (int)kindB) + 3);
        foreach (var c in PairCorpus.For(kindA, kindB))
        {
            // Move the pair's centre to a random point well inside ±25,000 mm.
            Point2 centre = (c.A.Reference.Centre + c.B.Reference.Centre) * 0.5;
            Point2 target = new(gen.Uniform(-21000, 21000), gen.Uniform(-21000, 21000));
            Point2 offset = target - centre;
            var a2 = c.A.Translated(offset);
            var b2 = c.B.Translated(offset);
            var moved = new PairCase(c.Index, a2, b2, c.Scenario, ReferenceGeometry.Contact(a2.Reference, b2.Reference));
            if (moved.Decided != c.Decided || moved.Reference.Intersect != c.Reference.Intersect)
            {
                // Rounding the moved spec to float crossed the touching band: not comparable.
                continue;
            }

            log.Case();
            var before = CollisionDetector.Detect(c.A.Shape, c.B.Shape);
            var after = CollisionDetector.Detect(a2.Shape, b2.Shape);
            var back = after.Intersect
                ? new CollisionDetectionResult(true, after.MinimumTranslationVector, after.NormalAxis, after.ActionPoint - URWPGSim2D.Collision.Geometry.XZPlane.ToWorld(offset.ToVector2()))
                : after;
            // Same MTV. The action point is not compared: for a grazing contact the overlap is a
            // long sliver whose position along the contact moves a lot when rounding the moved
            // shapes to float shifts an edge by 0.002 mm. It must still lie in the moved overlap.
            string? why = ContactComparison.Difference(before, back, c, compareActionPoints: false);
            log.Check(why is null, $"{c}: {why}; moved by {offset}: {after}; before: {before}");
            if (after.Intersect)
            {
                Point2 p = Point2.FromWorld(after.ActionPoint);
                double outside = System.Math.Max(a2.Reference.SignedDistance(p), b2.Reference.SignedDistance(p));
                log.Check(outside <= Tolerances.ActionPoint, $"{c}: moved by {offset}, the action point {p} is {outside:R} mm outside");
            }
        }

        log.AssertNone(PairCorpus.CasesPerPair * 9 / 10);
    }
}
