namespace URWPGSim2D.Collision.Tests.Shapes;

public sealed class KDop8Tests
{
    private static readonly double Half = Math.Sqrt(0.5);

    [Fact]
    public void WrongNumberOfSlabsIsRejected()
    {
        ArgumentAssert.Throws("min", () => _ = new KDop8([0, 0, 0], [1, 1, 1, 1]), "4 slab minima", "got 3");
        ArgumentAssert.Throws("max", () => _ = new KDop8([0, 0, 0, 0], [1, 1, 1, 1, 1]), "4 slab maxima", "got 5");
    }

    [Fact]
    public void NonFiniteSlabIsRejectedNamingItsIndex()
    {
        ArgumentAssert.Throws("min[2]", () => _ = new KDop8([0, 0, float.NaN, 0], [1, 1, 1, 1]), "finite", "NaN");
        ArgumentAssert.Throws("max[1]", () => _ = new KDop8([0, 0, 0, 0], [1, float.PositiveInfinity, 1, 1]), "finite", "Infinity");
    }

    [Fact]
    public void MinGreaterThanMaxIsRejectedNamingTheValues() =>
        ArgumentAssert.Throws("min", () => _ = new KDop8([0, 0, 0, 5], [1, 1, 1, 4]), "min[3] (5)", "max[3] (4)");

    [Fact]
    public void SlabsWithNoCommonPointAreRejected() =>
        ArgumentAssert.Throws("min", () => _ = new KDop8([0, 0, 10, -1], [1, 1, 11, 1]), "no point in common");

    [Fact]
    public void FromPointsRejectsNoPointsAndNonFinitePoints()
    {
        ArgumentAssert.Throws("points", () => KDop8.FromPoints([]), "at least one point");
        ArgumentAssert.Throws("points[1]", () => KDop8.FromPoints([new(0, 0), new(float.NaN, 1)]), "finite", "NaN");
    }

    [Fact]
    public void ActiveSlabsKeepTheirExactValuesFarFromTheOrigin()
    {
        // An octagon near (24000, 24000): every slab touches it. The slabs must come back exactly
        // (the first implementation grew diagonal slabs by 5e-7 × 25,000 = 0.0125 mm).
        float[] min = [23990, 23990, (float)(48000 * Half - 10), -10];
        float[] max = [24010, 24010, (float)(48000 * Half + 10), 10];
        var k = new KDop8(min, max);
        Assert.Equal(8, k.Vertices.Length);
        for (int i = 0; i < 4; i++)
        {
            Assert.Equal(min[i], k.GetMin(i));
            Assert.Equal(max[i], k.GetMax(i));
        }
    }

    [Fact]
    public void LooseSlabsAreTightenedOutward()
    {
        // A box with diagonal slabs far outside: they move in to the corners, rounded outward.
        var k = new KDop8([0, 0, -100, -100], [10, 10, 100, 100]);
        Assert.Equal(4, k.Vertices.Length);
        Assert.Equal(0f, k.GetMin(2));
        Assert.InRange(k.GetMax(2), 20 * Half, MathF.BitIncrement((float)(20 * Half)));
        Assert.InRange(k.GetMin(3), MathF.BitDecrement((float)(-10 * Half)), -10 * Half);
        Assert.InRange(k.GetMax(3), 10 * Half, MathF.BitIncrement((float)(10 * Half)));
    }

    [Fact]
    public void OctagonHasExactVerticesAndSlabNormalsCounterClockwise()
    {
        var k = new KDop8([-10, -10, -10, -10], [10, 10, 10, 10]);
        double c = 10 * Math.Sqrt(2) - 10;
        var expected = new Point2[] { new(-10, -c), new(-c, -10), new(c, -10), new(10, -c), new(10, c), new(c, 10), new(-c, 10), new(-10, c) };
        var v = k.Vertices.ToArray().Select(Point2.From).ToArray();
        Assert.Equal(8, v.Length);
        Assert.All(expected, e => Assert.Contains(v, p => Point2.Distance(p, e) < 1e-5));
        AssertConvexCounterClockwiseWithSlabNormals(k);
    }

    [Fact]
    public void FromAabbIsTheBox()
    {
        var k = KDop8.FromAabb(new Aabb(new(-3, 2), new(7, 5)));
        Assert.Equal(
            new[] { new Vector2(-3, 2), new Vector2(7, 2), new Vector2(7, 5), new Vector2(-3, 5) }.OrderBy(p => p.X).ThenBy(p => p.Y),
            k.Vertices.ToArray().OrderBy(p => p.X).ThenBy(p => p.Y));
        AssertConvexCounterClockwiseWithSlabNormals(k);
    }

    [Fact]
    public void PointAndFlatSetsGiveOneOrTwoVertices()
    {
        var point = KDop8.FromPoints([new(24000.5f, -3)]);
        Assert.Equal([new Vector2(24000.5f, -3)], point.Vertices.ToArray());

        var flat = KDop8.FromPoints([new(0, 0), new(10, 0), new(4, 0)]);
        Assert.Equal(2, flat.Vertices.Length);
        AssertConvexCounterClockwiseWithSlabNormals(flat);

        var diagonal = KDop8.FromPoints([new(-20000, -20000), new(-19990, -19990)]);
        Assert.Equal(2, diagonal.Vertices.Length);
        AssertConvexCounterClockwiseWithSlabNormals(diagonal);
        Assert.Equal(1, Math.Abs(Vector2.Dot(diagonal.View().Normals[0], new((float)Half, (float)-Half))), 1e-6);
    }

    [Fact]
    public void FromPointsEnclosesEveryPointAndIsTight()
    {
        var gen = new RandomShapes(4242);
        for (int n = 0; n < 300; n++)
        {
            Point2 centre = new(gen.Uniform(-24000, 24000), gen.Uniform(-24000, 24000));
            double size = gen.Size();
            var points = Enumerable.Range(0, gen.Int(1, 10))
                .Select(_ => (centre + new Point2(gen.Uniform(-size, size), gen.Uniform(-size, size)) * 0.5).ToVector2()).ToArray();
            var k = KDop8.FromPoints(points);
            for (int i = 0; i < 4; i++)
            {
                var proj = points.Select(p => ReferenceShape.SlabProjections(Point2.From(p))[i]).ToArray();
                Assert.True(k.GetMin(i) <= proj.Min() && proj.Max() <= k.GetMax(i), $"axis {i}: a point is outside");
                Assert.True(MathF.BitIncrement(k.GetMin(i)) > proj.Min() && MathF.BitDecrement(k.GetMax(i)) < proj.Max(), $"axis {i}: not tight");
            }

            var polygon = ReferenceShape.FromPoints(k.Vertices.ToArray().Select(Point2.From));
            Assert.All(points, p => Assert.True(polygon.SignedDistance(Point2.From(p)) <= 2e-3, $"{p} is outside the vertex polygon"));
            AssertConvexCounterClockwiseWithSlabNormals(k);
        }
    }

    [Fact]
    public void VerticesAreTheExactSlabRegionRoundedToFloat()
    {
        var gen = new RandomShapes(77);
        for (int n = 0; n < 500; n++)
        {
            var shape = gen.Create(ShapeKind.KDop8, new(gen.Uniform(-24000, 24000), gen.Uniform(-24000, 24000)), gen.Size());
            var k = shape.Shape.AsKDop8();

            // The exact region of the slabs the 8-DOP holds (FromPoints rounds its slabs outward).
            var exact = ReferenceShape.KDop8(
                Enumerable.Range(0, 4).Select(i => (double)k.GetMin(i)).ToArray(),
                Enumerable.Range(0, 4).Select(i => (double)k.GetMax(i)).ToArray());

            // Rounding to float moves a vertex by at most half an ulp per coordinate: 2⁻¹⁰ mm
            // between 16,384 and 32,768 mm, so √2 · 2⁻¹⁰ ≈ 0.0014 mm in the plane.
            const double rounding = 1.4e-3;
            Assert.All(k.Vertices.ToArray(), v => Assert.True(Math.Abs(exact.SignedDistance(Point2.From(v))) <= rounding, $"{v} is off the boundary of {exact}"));
            Assert.All(exact.Core, e => Assert.Contains(k.Vertices.ToArray(), v => Point2.Distance(Point2.From(v), e) <= rounding));
            AssertConvexCounterClockwiseWithSlabNormals(k);
        }
    }

    [Fact]
    public void TranslatedMovesTheSlabsOutward()
    {
        var k = new KDop8([0, 0, 2, -6], [10, 10, 12, 6]);
        var offset = new Vector2(12345.67f, -23456.78f);
        var moved = k.Translated(offset);
        var d = ReferenceShape.SlabProjections(Point2.From(offset));
        for (int i = 0; i < 4; i++)
        {
            Assert.InRange(k.GetMin(i) + d[i] - moved.GetMin(i), 0, 0.004);
            Assert.InRange(moved.GetMax(i) - (k.GetMax(i) + d[i]), 0, 0.004);
        }
    }

    [Fact]
    public void OverlapsIsStrictAndBoundingCircleHoldsEveryVertex()
    {
        var a = new KDop8([-10, -10, -10, -10], [10, 10, 10, 10]);
        Assert.True(a.Overlaps(new KDop8([5, 5, 5, -5], [15, 15, 15, 5])));
        Assert.False(a.Overlaps(new KDop8([-5, -5, 10, -5], [15, 15, 20, 5])));
        foreach (var v in a.Vertices)
        {
            Assert.True(Vector2.Distance(v, a.BoundingCircle.Center) <= a.BoundingCircle.Radius * (1 + 1e-6f));
        }
    }

    // CCW, every normal one of the eight slab directions, perpendicular and outward to its edge.
    private static void AssertConvexCounterClockwiseWithSlabNormals(in KDop8 k)
    {
        var view = k.View();
        var v = view.Vertices.ToArray().Select(Point2.From).ToArray();
        var normals = view.Normals.ToArray();
        if (v.Length == 1)
        {
            Assert.Empty(normals);
            return;
        }

        Assert.Equal(v.Length, normals.Length);
        for (int i = 0; i < v.Length; i++)
        {
            Point2 n = Point2.From(normals[i]);
            double angle = Math.Atan2(n.Y, n.X) / (Math.PI / 4);
            Assert.Equal(Math.Round(angle), angle, 1e-6);
            Point2 edge = v[(i + 1) % v.Length] - v[i];
            if (edge.Length > 0.1)
            {
                Assert.True(Point2.Cross(n, edge) > 0 && Math.Abs(Point2.Dot(n, edge)) <= 2e-3, $"normal {n} does not fit edge {edge}");
            }

            Assert.All(v, q => Assert.True(Point2.Dot(n, q - v[i]) <= 2e-3, $"vertex {q} is outside edge {i}"));
        }
    }
}
