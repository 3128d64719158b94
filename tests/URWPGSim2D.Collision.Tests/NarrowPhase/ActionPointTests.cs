namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>The action point lies in the contact region: inside (or on) both shapes.</summary>
public sealed class ActionPointTests
{
    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void ActionPointLiesInsideBothShapes(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var (c, r) in PairCorpus.Overlapping(kindA, kindB))
        {
            log.Case();
            Point2 p = Point2.FromWorld(r.ActionPoint);
            double outsideA = c.A.Reference.SignedDistance(p), outsideB = c.B.Reference.SignedDistance(p);
            log.Check(
                Math.Max(outsideA, outsideB) <= Tolerances.ActionPoint,
                $"{c}: action point {p} is {outsideA:R} mm outside a and {outsideB:R} mm outside b ({r})");
        }

        log.AssertNone(PairCorpus.CasesPerPair / 4);
    }
}
