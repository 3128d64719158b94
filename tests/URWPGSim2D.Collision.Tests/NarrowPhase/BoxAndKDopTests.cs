namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// Boxes and 8-DOPs against each other (fixed axes), by hand. The action point is the area
/// centroid of the intersection.
/// </summary>
public sealed class BoxAndKDopTests
{
    private static readonly double Half = Math.Sqrt(0.5);
    private static readonly Aabb Box = new(new(0, 0), new(10, 10));

    // All slabs [−10, 10]: an octagon with vertices such as (10, 4.142).
    private static readonly KDop8 Octagon = new([-10, -10, -10, -10], [10, 10, 10, 10]);

    [Fact]
    public void BoxesOverlapping()
    {
        // x: a may move +20 or −2; z: +6 or −8. Least: −2 along x. Intersection [8, 10] × [2, 6].
        ContactAssert.Contact(Box, new Aabb(new(8, 2), new(20, 6)), -2, 0, 9, 4);
    }

    [Fact]
    public void BoxInsideBoxGetsTheTrueMtv()
    {
        // a = [4, 6] × [4, 5] inside b: ±x 6, +z 6, −z 5. Intersection = a.
        ContactAssert.Contact(new Aabb(new(4, 4), new(6, 5)), Box, 0, -5, 5, 4.5);
    }

    [Fact]
    public void FlatBoxInsideABox()
    {
        // A zero-height box (a segment) at z = 4: least move −4 along z.
        ContactAssert.Contact(new Aabb(new(2, 4), new(8, 4)), Box, 0, -4, 5, 4);
    }

    [Fact]
    public void BoxesTouchingAlongAnEdgeOrAtACornerAreApart()
    {
        ContactAssert.Apart(Box, new Aabb(new(10, 0), new(20, 10)));
        ContactAssert.Apart(Box, new Aabb(new(10, 10), new(20, 20)));
        ContactAssert.Apart(Box, new Aabb(new(10.001f, 0), new(20, 10)));
    }

    [Fact]
    public void OctagonsMeetingOnADiagonalFace()
    {
        // b = the octagon moved by (12, 12): diagonal overlap 10 − (−10 + 24√½) = 20 − 24√½ ≈ 3.029,
        // less than the x and z overlaps (8). The intersection is symmetric about x = z and about
        // x + z = 12, so its centroid is (6, 6).
        float shift = (float)(24 * Half);
        var b = new KDop8([2, 2, -10 + shift, -10], [22, 22, 10 + shift, 10]);
        double depth = 20 - 24 * Half;
        ContactAssert.Contact(Octagon, b, -depth * Half, -depth * Half, 6, 6, 1e-3);
    }

    [Fact]
    public void OctagonsTouchingOnADiagonalFaceAreApart()
    {
        // b's lower diagonal slab starts exactly where a's ends: x and z overlap, diagonal only touches.
        float s = (float)(10 * Math.Sqrt(2));
        ContactAssert.Apart(Octagon, new KDop8([-10 + s, -10 + s, 10, -10], [10 + s, 10 + s, 30, 10]));
    }

    [Fact]
    public void BoxAgainstDiamond()
    {
        // Diamond with tips (8, 5), (24, 5), (16, −3), (16, 13): its left tip enters the box by 2.
        // Other axes: z 13, diagonals 7√2 ≈ 4.95. Intersection: triangle (8, 5), (10, 3), (10, 7).
        var diamond = new KDop8([8, -3, (float)(13 * Half), (float)(3 * Half)], [24, 13, (float)(29 * Half), (float)(19 * Half)]);
        ContactAssert.Contact(Box, diamond, -2, 0, 28.0 / 3, 5, 1e-3);
    }

    [Fact]
    public void PointKDop8InsideABox()
    {
        // A single point (3, 4): least move out is −3 along x; the intersection is the point itself.
        var point = KDop8.FromPoints([new(3, 4)]);
        Assert.Equal(1, point.Vertices.Length);
        ContactAssert.Contact(point, Box, -3, 0, 3, 4);
    }

    [Fact]
    public void KDop8FromABoxBehavesLikeTheBox()
    {
        var other = new Aabb(new(8, 2), new(20, 6));
        var viaKDop = CollisionDetector.Detect(KDop8.FromAabb(Box), other);
        var viaBox = CollisionDetector.Detect(Box, other);
        Assert.Equal(viaBox.MinimumTranslationVector.X, viaKDop.MinimumTranslationVector.X, 1e-4);
        Assert.Equal(viaBox.MinimumTranslationVector.Z, viaKDop.MinimumTranslationVector.Z, 1e-4);
        Assert.Equal(viaBox.ActionPoint.X, viaKDop.ActionPoint.X, 1e-4);
        Assert.Equal(viaBox.ActionPoint.Z, viaKDop.ActionPoint.Z, 1e-4);
    }

    [Fact]
    public void FarFromTheOriginKeepsTheAccuracyGoal()
    {
        // The diamond case moved to (24000, 24000): diagonal slabs near 34,000 mm.
        const float X = 24000, Z = 24000;
        float d2 = (float)((X + Z) * Half), d3 = (float)((X - Z) * Half);
        var box = new Aabb(new(X, Z), new(X + 10, Z + 10));
        var diamond = new KDop8(
            [X + 8, Z - 3, d2 + (float)(13 * Half), d3 + (float)(3 * Half)],
            [X + 24, Z + 13, d2 + (float)(29 * Half), d3 + (float)(19 * Half)]);
        ContactAssert.Contact(box, diamond, -2, 0, X + 28.0 / 3, Z + 5, Tolerances.Depth);
    }
}
