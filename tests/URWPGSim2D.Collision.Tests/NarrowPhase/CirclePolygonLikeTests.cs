namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// Circle against box, 8-DOP, polygon and segment (Voronoi regions), by hand. The action point
/// is the middle of the overlap on the line through the circle's centre along the normal.
/// </summary>
public sealed class CirclePolygonLikeTests
{
    private static readonly double Half = Math.Sqrt(0.5);
    private static readonly Aabb Box = new(new(0, 0), new(10, 10));

    [Fact]
    public void BoxEdgeRegion()
    {
        // Centre 2 below the bottom edge, radius 3: depth 1 along −z; overlap on x = 5 is z ∈ [0, 1].
        ContactAssert.Contact(new Circle(new(5, -2), 3), Box, 0, -1, 5, 0.5);
    }

    [Fact]
    public void BoxVertexRegion()
    {
        // Centre 5 from the corner (10, 10) along (0.6, 0.8), radius 5.1: depth 0.1.
        // On the line c + t·n the box covers t ≤ −5, the circle t ≥ −5.1: middle t = −5.05.
        ContactAssert.Contact(new Circle(new(13, 14), 5.1f), Box, 0.06, 0.08, 13 - 0.6 * 5.05, 14 - 0.8 * 5.05);
    }

    [Fact]
    public void CircleNearACornerButOutsideItIsNotAContact()
    {
        // Overlaps the box's x and z ranges (the original's corner false positive), but the corner
        // is √32 ≈ 5.66 > 5 away.
        ContactAssert.Apart(new Circle(new(14, 14), 5), Box);
    }

    [Fact]
    public void CentreInsideTheBoxLeavesThroughTheNearestEdge()
    {
        // Nearest edge x = 0 at distance 3: depth r + 3 = 4 along −x; overlap on z = 5 is x ∈ [2, 4].
        ContactAssert.Contact(new Circle(new(3, 5), 1), Box, -4, 0, 3, 5);
    }

    [Fact]
    public void BoxDeepInsideALargeCircle()
    {
        // Centre (4, 5): nearest edge x = 0 at 4: depth 104 along −x; the line z = 5 crosses the box at x ∈ [0, 10].
        ContactAssert.Contact(new Circle(new(4, 5), 100), Box, -104, 0, 5, 5);
    }

    [Fact]
    public void TouchingAnEdgeOrACornerIsNotAContact()
    {
        ContactAssert.Apart(new Circle(new(5, -3), 3), Box);
        ContactAssert.Apart(new Circle(new(13, 14), 5), Box);
    }

    [Fact]
    public void OctagonDiagonalFace()
    {
        // Regular-ish octagon: all slabs [−10, 10]. Centre 12 out along (√½, √½), radius 3: depth 1.
        var octagon = new KDop8([-10, -10, -10, -10], [10, 10, 10, 10]);
        var c = new Circle(new((float)(12 * Half), (float)(12 * Half)), 3);
        ContactAssert.Contact(c, octagon, Half, Half, 9.5 * Half, 9.5 * Half);
    }

    [Fact]
    public void OctagonVertexRegion()
    {
        // Vertex where x = 10 meets (x + z)√½ = 10: (10, 10√2 − 10). Centre 4 out along 20°, radius 5.
        var octagon = new KDop8([-10, -10, -10, -10], [10, 10, 10, 10]);
        double vx = 10, vz = 10 * Math.Sqrt(2) - 10;
        double nx = Math.Cos(Math.PI / 9), nz = Math.Sin(Math.PI / 9);
        var c = new Circle(new((float)(vx + 4 * nx), (float)(vz + 4 * nz)), 5);
        ContactAssert.Contact(c, octagon, nx, nz, vx - 0.5 * nx, vz - 0.5 * nz, 1e-3);
    }

    [Fact]
    public void FlatKDop8ActsAsASegment()
    {
        var flat = KDop8.FromPoints([new(0, 0), new(10, 0)]);
        Assert.Equal(2, flat.Vertices.Length);
        ContactAssert.Contact(new Circle(new(5, 2), 3), flat, 0, 1, 5, 0);
    }

    [Fact]
    public void TriangleHypotenuseGivenClockwise()
    {
        // Triangle (0,0), (10,0), (0,10) listed clockwise; hypotenuse x + z = 10, outward (√½, √½).
        var triangle = new ConvexPolygon([new(0, 0), new(0, 10), new(10, 0)]);
        var c = new Circle(new((float)(5 + 2 * Half), (float)(5 + 2 * Half)), 3);
        ContactAssert.Contact(c, triangle, Half, Half, 5 - 0.5 * Half, 5 - 0.5 * Half);
    }

    [Fact]
    public void TriangleContainingTheCircle()
    {
        // Centre (2, 3) inside, nearest edge x = 0 at 2: depth 1 + 2 = 3 along −x.
        var triangle = new ConvexPolygon([new(0, 0), new(10, 0), new(0, 10)]);
        ContactAssert.Contact(new Circle(new(2, 3), 1), triangle, -3, 0, 2, 3);
    }

    [Fact]
    public void SegmentFromEitherSide()
    {
        var s = new Segment(new(0, 0), new(10, 0));
        ContactAssert.Contact(new Circle(new(5, 2), 3), s, 0, 1, 5, 0);
        ContactAssert.Contact(new Circle(new(5, -2), 3), s, 0, -1, 5, 0);
    }

    [Fact]
    public void SegmentEndRegion()
    {
        // 3 past the end (10, 0), radius 4: depth 1 along +x; the segment lies on the line, the overlap is x ∈ [9, 10].
        ContactAssert.Contact(new Circle(new(13, 0), 4), new Segment(new(0, 0), new(10, 0)), 1, 0, 9.5, 0);
    }

    [Fact]
    public void CentreOnTheSegmentPushesByTheRadiusAcrossIt()
    {
        var r = CollisionDetector.Detect(new Circle(new(5, 0), 2), new Segment(new(0, 0), new(10, 0)));
        Assert.True(r.Intersect);
        Assert.Equal(2, r.Depth, 1e-6);
        Assert.Equal(0, r.NormalAxis.X, 1e-6);
        Assert.Equal(1, Math.Abs(r.NormalAxis.Z), 1e-6);
    }

    [Fact]
    public void TouchingASegmentIsNotAContact()
    {
        ContactAssert.Apart(new Circle(new(5, 3), 3), new Segment(new(0, 0), new(10, 0)));
        ContactAssert.Apart(new Circle(new(13, 0), 3), new Segment(new(0, 0), new(10, 0)));
    }
}
