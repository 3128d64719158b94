namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// The MTV is a translation that separates, and no shorter translation in any direction does:
/// checked by moving shape a and asking the library (and the reference) again.
/// </summary>
public sealed class MtvPropertyTests
{
    /// <summary>Extra push beyond the MTV: twice the accuracy goal, so that error cannot hide a wrong MTV.</summary>
    private const double Epsilon = 2 * Tolerances.Depth;

    /// <summary>How much shorter than the depth the "still overlapping" moves are.</summary>
    private const double Shortfall = 3 * Tolerances.Depth;

    private const int DirectionsPerCase = 8;

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void MovingAByTheMtvLeavesTheShapesJustTouching(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        foreach (var (c, r) in PairCorpus.Overlapping(kindA, kindB))
        {
            log.Case();
            Point2 mtv = Point2.FromWorld(r.MinimumTranslationVector);
            Point2 n = Point2.FromWorld(r.NormalAxis);

            // Library: a little past the MTV they are apart.
            var moved = c.A.Translated(mtv * (1 + 1e-4) + n * Epsilon);
            var after = CollisionDetector.Detect(moved.Shape, c.B.Shape);
            log.Check(!after.Intersect, $"{c}: still {after} after moving a by the MTV {mtv} (+ {Epsilon} mm)");

            // Reference: exactly at the MTV they touch (neither overlap nor gap beyond the goal).
            var touching = c.A.Translated(mtv);
            double depth = ReferenceGeometry.Contact(touching.Reference, c.B.Reference).SignedDepth;
            log.Check(Math.Abs(depth) <= Tolerances.Depth, $"{c}: after moving a by the MTV {mtv} the reference depth is {depth:R}");
        }

        log.AssertNone(PairCorpus.CasesPerPair / 4);
    }

    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void NoShorterMoveInAnyDirectionSeparatesTheShapes(ShapeKind kindA, ShapeKind kindB)
    {
        var log = new FailureLog();
        var gen = new RandomShapes(31 * (5 * (int)kindA + (int)kindB) + 17);
        foreach (var (c, r) in PairCorpus.Overlapping(kindA, kindB))
        {
            if (r.Depth <= Shortfall)
            {
                continue;
            }

            log.Case();
            Point2 n = Point2.FromWorld(r.NormalAxis);
            for (int k = 0; k <= DirectionsPerCase; k++)
            {
                // k = 0: along the MTV itself; then random directions.
                Point2 direction = k == 0 ? n : gen.Direction();
                var moved = c.A.Translated(direction * (r.Depth - Shortfall));
                var after = CollisionDetector.Detect(moved.Shape, c.B.Shape);
                log.Check(after.Intersect, $"{c}: moving a by {r.Depth - Shortfall:R} mm along {direction} separates them, but the MTV is {r.Depth:R} mm");
            }
        }

        log.AssertNone(PairCorpus.CasesPerPair / 10);
    }
}
