namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>Assertions for hand-computed contacts; each checks both argument orders.</summary>
public static class ContactAssert
{
    /// <summary>Default tolerance for hand-computed values near the origin, mm.</summary>
    public const double Tight = 1e-4;

    /// <summary>
    /// Asserts that a overlaps b with MTV (mtvX, mtvZ) and action point (pointX, pointZ), and that
    /// b against a gives the negated MTV and normal and the same action point.
    /// </summary>
    public static CollisionDetectionResult Contact(Shape a, Shape b, double mtvX, double mtvZ, double pointX, double pointZ, double tolerance = Tight)
    {
        var r = CollisionDetector.Detect(a, b);
        Assert.True(r.Intersect, $"expected a contact, got {r}");
        double depth = Math.Sqrt(mtvX * mtvX + mtvZ * mtvZ);
        Near(r, "MTV", r.MinimumTranslationVector.X, r.MinimumTranslationVector.Z, mtvX, mtvZ, tolerance);
        Near(r, "normal", r.NormalAxis.X, r.NormalAxis.Z, mtvX / depth, mtvZ / depth, tolerance / Math.Min(1, depth));
        Near(r, "action point", r.ActionPoint.X, r.ActionPoint.Z, pointX, pointZ, tolerance);
        Assert.Equal(depth, r.Depth, tolerance);
        Assert.True(r.MinimumTranslationVector.Y == 0 && r.NormalAxis.Y == 0 && r.ActionPoint.Y == 0, $"Y must be 0: {r}");

        var s = CollisionDetector.Detect(b, a);
        Assert.True(s.Intersect, $"b against a: expected a contact, got {s}");
        Near(s, "swapped MTV", s.MinimumTranslationVector.X, s.MinimumTranslationVector.Z, -mtvX, -mtvZ, tolerance);
        Near(s, "swapped action point", s.ActionPoint.X, s.ActionPoint.Z, pointX, pointZ, tolerance);
        return r;
    }

    /// <summary>Asserts that a and b do not overlap, in both orders, with an all-zero result.</summary>
    public static void Apart(Shape a, Shape b)
    {
        Assert.Equal(CollisionDetectionResult.None, CollisionDetector.Detect(a, b));
        Assert.Equal(CollisionDetectionResult.None, CollisionDetector.Detect(b, a));
    }

    private static void Near(CollisionDetectionResult r, string what, double x, double z, double ex, double ez, double tolerance) =>
        Assert.True(
            Math.Abs(x - ex) <= tolerance && Math.Abs(z - ez) <= tolerance,
            $"{what}: expected ({ex}, {ez}), got ({x}, {z}) in {r}");
}
