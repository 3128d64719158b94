namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>Segments against segments and polygon-like shapes, by hand. A segment has no area: only crossing counts.</summary>
public sealed class SegmentTests
{
    private static readonly Segment Horizontal = new(new(-5, 0), new(5, 0));

    [Fact]
    public void CrossingSegments()
    {
        // b spans z ∈ [−2, 8] at x = 0: a moves −2 along z (or +8; along x ±5). Action point: the crossing.
        ContactAssert.Contact(Horizontal, new Segment(new(0, -2), new(0, 8)), 0, -2, 0, 0);
    }

    [Fact]
    public void TJunctionOnlyTouches() =>
        ContactAssert.Apart(Horizontal, new Segment(new(0, 0), new(0, 8)));

    [Fact]
    public void CollinearOverlappingSegmentsOnlyTouch() =>
        ContactAssert.Apart(new Segment(new(0, 0), new(10, 0)), new Segment(new(5, 0), new(15, 0)));

    [Fact]
    public void ParallelSegmentsAreApart() =>
        ContactAssert.Apart(new Segment(new(0, 0), new(10, 0)), new Segment(new(0, 0.001f), new(10, 0.001f)));

    [Fact]
    public void SegmentThroughABox()
    {
        // At z = 3 through [0, 10]²: −3 along z is least (+7 up, ±15 along x). Inside part x ∈ [0, 10].
        ContactAssert.Contact(new Segment(new(-5, 3), new(15, 3)), new Aabb(new(0, 0), new(10, 10)), 0, -3, 5, 3);
    }

    [Fact]
    public void SegmentInsideATriangleGetsTheTrueMtv()
    {
        // (2, 1)–(4, 1) in triangle (0,0), (10,0), (0,10): −1 along z; x = 0 needs 4; hypotenuse (10 − 3)/√2.
        var triangle = new ConvexPolygon([new(0, 0), new(10, 0), new(0, 10)]);
        ContactAssert.Contact(new Segment(new(2, 1), new(4, 1)), triangle, 0, -1, 3, 1);
    }

    [Fact]
    public void SegmentThroughAnOctagon()
    {
        // At z = 2 across the octagon with all slabs [−10, 10]: +8 along z; diagonals need ≥ 22.7.
        // Inside part x ∈ [−10, 10].
        var octagon = new KDop8([-10, -10, -10, -10], [10, 10, 10, 10]);
        ContactAssert.Contact(new Segment(new(-20, 2), new(20, 2)), octagon, 0, 8, 0, 2);
    }

    [Fact]
    public void SegmentAlongAPolygonEdgeOnlyTouches() =>
        ContactAssert.Apart(new Segment(new(2, 0), new(8, 0)), new Aabb(new(0, 0), new(10, 10)));
}
