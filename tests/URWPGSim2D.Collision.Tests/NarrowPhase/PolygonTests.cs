namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>Convex polygons against polygons, boxes and 8-DOPs (SAT over edge normals), by hand.</summary>
public sealed class PolygonTests
{
    private static readonly ConvexPolygon Square = new([new(0, 0), new(10, 0), new(10, 10), new(0, 10)]);

    // Tip (8, 5) enters the square by 2; its slanted edges need 5.12 each way.
    private static readonly ConvexPolygon Wedge = new([new(8, 5), new(20, -5), new(20, 15)]);

    // Centre (5, 3), half-diagonal 4.
    private static readonly ConvexPolygon Diamond = new([new(9, 3), new(5, 7), new(1, 3), new(5, -1)]);

    [Fact]
    public void WedgeTipInASquare()
    {
        // Reference face: the square's side x = 10; the incident tip (8, 5) lies 2 below it, so the
        // action point is half way between the tip and the face: (9, 5).
        ContactAssert.Contact(Square, Wedge, -2, 0, 9, 5);
    }

    [Fact]
    public void SquareInsideATriangleGetsTheTrueMtv()
    {
        // Square [4, 6] × [3, 5] inside triangle (0,0), (20,0), (0,20): out through z = 0 needs 5,
        // through x = 0 needs 6, through the hypotenuse (20 − 7)/√2 ≈ 9.19.
        var small = new ConvexPolygon([new(4, 3), new(6, 3), new(6, 5), new(4, 5)]);
        var triangle = new ConvexPolygon([new(0, 0), new(20, 0), new(0, 20)]);
        ContactAssert.Contact(small, triangle, 0, -5, 5, 4);
    }

    [Fact]
    public void DeepOverlapOfEqualSquares()
    {
        // Offset (1, 3): a may move +9 or −11 along x, +7 or −13 along z; least +7 along z.
        // Intersection [1, 10] × [3, 10].
        var moved = new ConvexPolygon([new(1, 3), new(11, 3), new(11, 13), new(1, 13)]);
        ContactAssert.Contact(moved, Square, 0, 7, 5.5, 6.5);
    }

    [Fact]
    public void SharedEdgeOrVertexIsNotAContact()
    {
        ContactAssert.Apart(Square, new ConvexPolygon([new(10, 0), new(20, 0), new(20, 10), new(10, 10)]));
        ContactAssert.Apart(Square, new ConvexPolygon([new(10, 10), new(20, 10), new(20, 20), new(10, 20)]));
        ContactAssert.Apart(Square, new ConvexPolygon([new(10.001f, 0), new(20, 0), new(20, 10)]));
    }

    [Fact]
    public void DiamondTipInABox()
    {
        // Tip (5, 7) enters the box [0, 10] × [5, 15] by 2; diagonal axes need 7/√2 ≈ 4.95.
        // Reference face: the box's side z = 5; the tip is 2 below it: action point (5, 6).
        ContactAssert.Contact(Diamond, new Aabb(new(0, 5), new(10, 15)), 0, -2, 5, 6);
    }

    [Fact]
    public void DiamondTipInAnEightDop()
    {
        ContactAssert.Contact(Diamond, KDop8.FromAabb(new Aabb(new(0, 5), new(10, 15))), 0, -2, 5, 6);
    }

    [Fact]
    public void WindingDoesNotChangeTheAnswer()
    {
        var clockwise = new ConvexPolygon([new(20, 15), new(20, -5), new(8, 5)]);
        Assert.Equal(CollisionDetector.Detect(Square, Wedge), CollisionDetector.Detect(Square, clockwise));
    }

    [Fact]
    public void FarFromTheOriginKeepsTheAccuracyGoal()
    {
        var offset = new Vector2(-24000, 23000);
        var r = ContactAssert.Contact(Square.Translated(offset), Wedge.Translated(offset), -2, 0, -24000 + 9, 23005, Tolerances.Depth);
        Assert.True(r.Intersect);
    }
}
