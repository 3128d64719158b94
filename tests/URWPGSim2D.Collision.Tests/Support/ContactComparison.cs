namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// Decides whether two library results describe the same contact (for swap and translation
/// tests), allowing for genuine ties: when two directions are equally short, either is a correct
/// MTV, which is checked against the reference instead of against each other.
/// </summary>
public static class ContactComparison
{
    /// <summary>
    /// Null when <paramref name="first"/> and <paramref name="second"/> (already mapped into the
    /// same frame and order) agree; otherwise why not. <paramref name="pair"/> is the reference
    /// pair used to settle ties. Action points are compared only when
    /// <paramref name="compareActionPoints"/> is set and the MTVs agree (in a tie each normal has
    /// its own, equally valid, point).
    /// </summary>
    public static string? Difference(CollisionDetectionResult first, CollisionDetectionResult second, PairCase pair, bool compareActionPoints = true)
    {
        if (first.Intersect != second.Intersect)
        {
            return pair.Decided ? $"intersect {first.Intersect} vs {second.Intersect}" : null;
        }

        if (!first.Intersect)
        {
            return null;
        }

        if (Math.Abs(first.Depth - second.Depth) > Tolerances.Depth)
        {
            return $"depth {first.Depth:R} vs {second.Depth:R}";
        }

        Point2 mtv1 = Point2.FromWorld(first.MinimumTranslationVector), mtv2 = Point2.FromWorld(second.MinimumTranslationVector);
        if (Point2.Distance(mtv1, mtv2) <= Tolerances.Depth)
        {
            double apart = Point2.Distance(Point2.FromWorld(first.ActionPoint), Point2.FromWorld(second.ActionPoint));
            return !compareActionPoints || apart <= Tolerances.SameActionPoint ? null : $"action points {apart:R} mm apart";
        }

        // A tie: both directions must be minimal according to the reference.
        double depth = pair.Reference.SignedDepth;
        foreach (var r in new[] { first, second })
        {
            double along = ReferenceGeometry.DirectionalDepth(pair.A.Reference, pair.B.Reference, Point2.FromWorld(r.NormalAxis));
            if (along > depth + Tolerances.Depth)
            {
                return $"MTVs {mtv1} vs {mtv2} differ and normal {Point2.FromWorld(r.NormalAxis)} needs {along:R} mm, not the minimal {depth:R}";
            }
        }

        return null;
    }
}
