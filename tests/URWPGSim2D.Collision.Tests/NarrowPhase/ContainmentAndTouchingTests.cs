namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// Containment (true MTV, not a projection overlap) and exact touching for the pair kinds the
/// other analytic tests leave out, by hand. O is the octagon with every slab [−10, 10]: faces
/// x = ±10, z = ±10 and (±x ± z)√½ = 10.
/// </summary>
public sealed class ContainmentAndTouchingTests
{
    private static readonly double Half = Math.Sqrt(0.5);
    private static readonly KDop8 O = new([-10, -10, -10, -10], [10, 10, 10, 10]);
    private static readonly Aabb Box = new(new(0, 0), new(10, 10));

    [Fact]
    public void CircleInsideTheOctagon()
    {
        // Centre (2, 0): face x = 10 is 8 away, the nearest diagonal face 10 − 2√½ ≈ 8.59. Depth 8 + 1.
        ContactAssert.Contact(new Circle(new(2, 0), 1), O, 9, 0, 2, 0);
    }

    [Fact]
    public void OctagonInsideALargeCircle()
    {
        // Centre (0, 1): face z = 10 is 9 away (diagonal faces 10 − √½·1 ≈ 9.29). Depth 100 + 9.
        // The octagon spans z ∈ [−10, 10] on x = 0, so the overlap's middle is (0, 0).
        ContactAssert.Contact(new Circle(new(0, 1), 100), O, 0, 109, 0, 0);
    }

    [Fact]
    public void CircleTouchingOrJustApartFromTheOctagonOrAPolygon()
    {
        ContactAssert.Apart(new Circle(new(13, 0), 3), O);
        ContactAssert.Apart(new Circle(new(5, -3.001f), 3), new ConvexPolygon([new(0, 0), new(10, 0), new(0, 10)]));
    }

    [Fact]
    public void BoxInsideTheOctagon()
    {
        // Box [1, 3] × [1, 2]: ±x needs 9 / 13, ±z 9 / 12, diagonal (x + z)√½ needs 10 − 2√½ ≈ 8.59 (least).
        double depth = 10 - 2 * Half;
        ContactAssert.Contact(new Aabb(new(1, 1), new(3, 2)), O, depth * Half, depth * Half, 2, 1.5);
    }

    [Fact]
    public void SmallOctagonInsideTheOctagon()
    {
        // Slabs [−1, 1] around (3, 0): +x needs 10 − 2 = 8; diagonals 10 − (3√½ − 1) ≈ 8.88.
        double d = 3 * Half;
        var small = new KDop8([2, -1, (float)(d - 1), (float)(d - 1)], [4, 1, (float)(d + 1), (float)(d + 1)]);
        ContactAssert.Contact(small, O, 8, 0, 3, 0);
    }

    [Fact]
    public void TriangleInsideTheOctagon()
    {
        // Right triangle (−1, −1), (2, −1), (−1, 2): leaving along −(√½, √½) needs 10 + √½ (its
        // highest (x + z)√½ is √½); every other axis needs ≥ 11. Centroid (0, 0).
        var triangle = new ConvexPolygon([new(-1, -1), new(2, -1), new(-1, 2)]);
        double depth = 10 + Half;
        ContactAssert.Contact(triangle, O, -depth * Half, -depth * Half, 0, 0);
    }

    [Fact]
    public void TriangleInsideABox()
    {
        // Triangle (2, 2), (6, 2), (2, 5) in [0, 10]²: −z needs 5 (least), −x 6, its hypotenuse
        // normal (0.6, 0.8) needs 5.2. Reference face: the box's side z = 0; incident edge: the
        // hypotenuse (6, 2)–(2, 5). Moving its ends half way to z = 0 leaves the triangle, so the
        // action point is the middle of the clipped incident edge itself, (4, 3.5): on the
        // triangle's boundary, inside the box.
        ContactAssert.Contact(new ConvexPolygon([new(2, 2), new(6, 2), new(2, 5)]), Box, 0, -5, 4, 3.5);
    }

    [Fact]
    public void SegmentInsideABox()
    {
        // (2, 3)–(5, 3): −z needs 3 (least), −x 5. The whole segment is the overlap.
        ContactAssert.Contact(new Segment(new(2, 3), new(5, 3)), Box, 0, -3, 3.5, 3);
    }

    [Fact]
    public void SegmentInsideTheOctagon()
    {
        // (−2, 1)–(2, 1): +z needs 9 (least), −z 11, diagonals ≥ 10.7, x 12.
        ContactAssert.Contact(new Segment(new(-2, 1), new(2, 1)), O, 0, 9, 0, 1);
    }

    [Fact]
    public void ShapesTouchingTheOctagonAreApart()
    {
        ContactAssert.Apart(new Aabb(new(10, -2), new(20, 2)), O);
        ContactAssert.Apart(new ConvexPolygon([new(10, 0), new(12, -1), new(12, 1)]), O);
        ContactAssert.Apart(new Segment(new(10, -2), new(10, 2)), O);

        // Diagonal touching needs slab values: no float point lies exactly on (x + z)√½ = 10.
        ContactAssert.Apart(new KDop8([0, 0, 10, -10], [20, 20, 20, 10]), O);
    }

    [Fact]
    public void ShapesTouchingABoxOrAPolygonAreApart()
    {
        ContactAssert.Apart(Box, new ConvexPolygon([new(10, 2), new(15, 5), new(10, 8)]));
        ContactAssert.Apart(new Segment(new(2, 0), new(8, 0)), new ConvexPolygon([new(0, 0), new(10, 0), new(0, 10)]));
        ContactAssert.Apart(new Segment(new(10, 12), new(12, 10)), Box);
    }
}
