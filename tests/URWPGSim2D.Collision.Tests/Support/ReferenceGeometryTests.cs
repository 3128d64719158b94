namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>The test reference against answers known by hand (a wrong reference would make every property test meaningless).</summary>
public sealed class ReferenceGeometryTests
{
    private static readonly ReferenceShape Square = ReferenceShape.Aabb(new(0, 0), new(10, 10));

    [Fact]
    public void HullDropsInteriorCollinearAndRepeatedPoints()
    {
        var hull = ReferenceGeometry.ConvexHull([new(0, 0), new(5, 0), new(10, 0), new(10, 10), new(3, 4), new(0, 10), new(0, 10)]);
        Assert.Equal([new(0, 0), new(10, 0), new(10, 10), new(0, 10)], hull);
        Assert.Equal([new(0, 0), new(9, 9)], ReferenceGeometry.ConvexHull([new(3, 3), new(0, 0), new(9, 9), new(6, 6)]));
        Assert.Equal([new(2, 2)], ReferenceGeometry.ConvexHull([new(2, 2), new(2, 2)]));
    }

    [Fact]
    public void SignedDistanceOfSquareCircleAndSegment()
    {
        Assert.Equal(-3, Square.SignedDistance(new(3, 5)), 12);
        Assert.Equal(5, Square.SignedDistance(new(13, 14)), 12);
        Assert.Equal(-1, ReferenceShape.Circle(new(0, 0), 4).SignedDistance(new(3, 0)), 12);
        Assert.Equal(2, ReferenceShape.Segment(new(0, 0), new(10, 0)).SignedDistance(new(5, -2)), 12);
        Assert.Equal(5, ReferenceShape.Segment(new(0, 0), new(10, 0)).SignedDistance(new(13, 4)), 12);
    }

    [Fact]
    public void ContactOfOverlappingContainedAndSeparatedShapes()
    {
        // Overlap: a = [8, 20] × [2, 6] must move +2 along x.
        var c = ReferenceGeometry.Contact(ReferenceShape.Aabb(new(8, 2), new(20, 6)), Square);
        Assert.Equal(2, c.SignedDepth, 12);
        Assert.Equal(new Point2(1, 0), c.Normal);

        // Containment: circle r 1 at (3, 5) inside the square leaves through x = 0: 3 + 1.
        c = ReferenceGeometry.Contact(ReferenceShape.Circle(new(3, 5), 1), Square);
        Assert.Equal(4, c.SignedDepth, 12);
        Assert.Equal(new Point2(-1, 0), c.Normal);

        // Circles 3-4-5: depth r₁ + r₂ − d = 1 along (a − b)/d.
        c = ReferenceGeometry.Contact(ReferenceShape.Circle(new(0, 0), 4), ReferenceShape.Circle(new(3, 4), 2));
        Assert.Equal(1, c.SignedDepth, 12);
        Assert.Equal(-0.6, c.Normal.X, 12);
        Assert.Equal(-0.8, c.Normal.Y, 12);

        // Apart: corner to corner, gap √2; normal (−1, −1)/√2 from b toward a; the "MTV" of a
        // separated pair brings a to touch b: (+1, +1).
        c = ReferenceGeometry.Contact(Square, ReferenceShape.Aabb(new(11, 11), new(12, 12)));
        Assert.Equal(-Math.Sqrt(2), c.SignedDepth, 12);
        Assert.False(c.Intersect);
        Assert.Equal(-Math.Sqrt(0.5), c.Normal.X, 12);
        Assert.Equal(1, c.Mtv.X, 12);
        Assert.Equal(1, c.Mtv.Y, 12);

        // Crossing segments: the shorter push, 2 along −z.
        c = ReferenceGeometry.Contact(ReferenceShape.Segment(new(-5, 0), new(5, 0)), ReferenceShape.Segment(new(0, -2), new(0, 8)));
        Assert.Equal(2, c.SignedDepth, 12);
        Assert.Equal(new Point2(0, -1), c.Normal);

        // Touching is not intersecting.
        Assert.False(ReferenceGeometry.Contact(Square, ReferenceShape.Aabb(new(10, 0), new(20, 10))).Intersect);
    }

    [Fact]
    public void DirectionalDepthIsTheDistanceToLeaveAlongADirection()
    {
        var b = ReferenceShape.Aabb(new(8, 2), new(20, 6));
        Assert.Equal(2, ReferenceGeometry.DirectionalDepth(Square, b, new(-1, 0)), 12);
        Assert.Equal(20, ReferenceGeometry.DirectionalDepth(Square, b, new(1, 0)), 12);
        Assert.Equal(8, ReferenceGeometry.DirectionalDepth(Square, b, new(0, -1)), 12);
        Assert.Equal(6, ReferenceGeometry.DirectionalDepth(Square, b, new(0, 1)), 12);

        // Circles of radii 4 and 6, centres 6 apart on x: 4 along x, 8 along z (6² + 8² = 10²).
        var c1 = ReferenceShape.Circle(new(0, 0), 4);
        var c2 = ReferenceShape.Circle(new(6, 0), 6);
        Assert.Equal(4, ReferenceGeometry.DirectionalDepth(c1, c2, new(-1, 0)), 12);
        Assert.Equal(8, ReferenceGeometry.DirectionalDepth(c1, c2, new(0, 1)), 12);

        // A circle in the square's corner region, moved along the diagonal.
        var corner = ReferenceShape.Circle(new(11, 11), 2);
        Assert.Equal(2 - Math.Sqrt(2), ReferenceGeometry.DirectionalDepth(corner, Square, new Point2(1, 1).Normalized()), 12);
        Assert.Equal(0, ReferenceGeometry.DirectionalDepth(ReferenceShape.Circle(new(20, 20), 1), Square, new(1, 0)));
    }

    [Fact]
    public void KDop8ReferenceIsTheOctagon()
    {
        var octagon = ReferenceShape.KDop8([-10, -10, -10, -10], [10, 10, 10, 10]);
        double c = 10 * Math.Sqrt(2) - 10;
        Assert.Equal(8, octagon.Core.Count);
        Assert.Contains(octagon.Core, p => Point2.Distance(p, new(10, c)) < 1e-12);
        Assert.Equal(-10, octagon.SignedDistance(Point2.Zero), 12);

        // The 8-DOP of a right triangle with legs on the axes is the triangle itself.
        var triangle = ReferenceShape.KDop8OfPoints([new Vector2(0, 0), new Vector2(10, 0), new Vector2(0, 10)]);
        Assert.Equal(3, triangle.Core.Count);
        Assert.All(triangle.Core, p => Assert.True(p.X == 0 || Math.Abs(p.Y) < 1e-12 || Math.Abs(p.X + p.Y - 10) < 1e-12));
    }
}
