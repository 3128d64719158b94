namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// The pair kernels have vector paths (shapes of three to eight vertices held in the eight lanes
/// of 256-bit vectors, <see cref="ConvexSatWide"/> and <see cref="CircleLanes"/>, or in two groups
/// of four, <see cref="ConvexSatLanes"/>; four faces at a time in <see cref="FaceLoops"/>) and a
/// scalar path (one face at a time), and all must give the same answers bit for bit, the sign of
/// a zero included: a last-bit difference can change a match. Each test calls both paths on the same
/// random pairs (the ranges: 5 to 1,600 mm, ±25,000 mm, containment, near touching,
/// apart) and compares every float's bits.
/// </summary>
public sealed class PairKernelPathTests
{
    private static readonly ShapeKind[] PolygonLike = [ShapeKind.Polygon, ShapeKind.Aabb, ShapeKind.KDop8, ShapeKind.Segment];

    [Fact]
    public void LanesSatEqualsTheScalarAndVectorLoopsBitForBit()
    {
        const int seed = 1010;
        var gen = new RandomShapes(seed);
        int lanes = 0, hits = 0;
        for (int trial = 0; trial < 12000; trial++)
        {
            var (a, b, _) = gen.Pair(PolygonLike[trial % 4], PolygonLike[(trial / 4) % 4]);
            try
            {
                var (va, na) = Outline(a.Shape);
                var (vb, nb) = Outline(b.Shape);
                var viewA = new ConvexView(va, na);
                var viewB = new ConvexView(vb, nb);
                var scalar = ConvexSat.Detect(viewA, viewB, vector: false);
                AssertSame(scalar, ConvexSat.Detect(viewA, viewB, vector: true));
                AssertSame(scalar, ConvexSat.Detect(viewA, viewB));
                bool scalarHit = ConvexSat.Depth(viewA, viewB, out ContactDepth scalarDepth, vector: false);
                Assert.Equal(scalar.Intersect, scalarHit);
                if (ConvexLanes.Fits(va.Length) && ConvexLanes.Fits(vb.Length))
                {
                    lanes++;
                    AssertSame(scalar, ConvexSatLanes.Detect(viewA, viewB));
                    Assert.Equal(scalarHit, ConvexSatLanes.Depth(viewA, viewB, out ContactDepth depth));
                    if (scalarHit)
                    {
                        AssertSame(scalarDepth, depth);
                        AssertSame(scalar, ConvexSatLanes.Complete(viewA, viewB, depth));
                    }
                }

                hits += scalar.Intersect ? 1 : 0;
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(seed, trial, new XunitException($"{a} vs {b}: {e.Message}"));
            }
        }

        Assert.InRange(lanes, 3000, 12000);
        Assert.InRange(hits, 3000, 11000);
    }

    [Fact]
    public void CircleVectorPathEqualsTheScalarPathBitForBit()
    {
        const int seed = 1011;
        var gen = new RandomShapes(seed);
        int hits = 0;
        for (int trial = 0; trial < 12000; trial++)
        {
            var (a, b, _) = gen.Pair(ShapeKind.Circle, PolygonLike[trial % 4]);
            try
            {
                var circle = a.Shape.AsCircle();
                var (v, n) = Outline(b.Shape);
                var view = new ConvexView(v, n);
                var scalar = CircleConvex.Detect(circle, view, vector: false);
                AssertSame(scalar, CircleConvex.Detect(circle, view, vector: true));
                AssertSame(scalar, CircleConvex.Detect(circle, view));
                Assert.Equal(scalar.Intersect, CircleConvex.Depth(circle, view, out ContactDepth scalarDepth, vector: false));
                Assert.Equal(scalar.Intersect, CircleConvex.Depth(circle, view, out ContactDepth depth));
                if (scalar.Intersect)
                {
                    AssertSame(scalarDepth, depth);
                    AssertSame(scalar, CircleConvex.Complete(circle, view, depth));
                    hits++;
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(seed, trial, new XunitException($"{a} vs {b}: {e.Message}"));
            }
        }

        Assert.InRange(hits, 3000, 11000);
    }

    [Fact]
    public void PackedPolygonLanesEqualTheScalarPathBitForBit()
    {
        // Polygons of at most eight vertices keep their lanes packed (PolygonLanes): the public
        // polygon–polygon and circle–polygon tests read them instead of the vertex arrays.
        const int seed = 1013;
        var gen = new RandomShapes(seed);
        int packed = 0, hits = 0;
        for (int trial = 0; trial < 16000; trial++)
        {
            bool circle = trial % 2 == 0;
            var (a, b, _) = gen.Pair(circle ? ShapeKind.Circle : ShapeKind.Polygon, ShapeKind.Polygon);
            try
            {
                var polygon = b.Shape.AsPolygon();
                var view = polygon.View();
                bool fits = PolygonLanes.Fits(view.Vertices.Length);
                CollisionDetectionResult scalar;
                if (circle)
                {
                    var c = a.Shape.AsCircle();
                    scalar = CircleConvex.Detect(c, view, vector: false);
                    AssertSame(scalar, CollisionDetector.Detect(c, polygon));
                    AssertSame(scalar.Swapped(), CollisionDetector.Detect(polygon, c));
                    if (fits && PolygonLanes.IsSupported)
                    {
                        AssertSame(scalar, CircleLanes.Detect(c, view));
                    }
                }
                else
                {
                    var other = a.Shape.AsPolygon();
                    scalar = ConvexSat.Detect(other.View(), view, vector: false);
                    AssertSame(scalar, CollisionDetector.Detect(other, polygon));
                    fits &= PolygonLanes.Fits(other.Vertices.Length);
                    if (fits && PolygonLanes.IsSupported)
                    {
                        AssertSame(scalar, ConvexSatWide.Detect(other.View(), view));
                    }
                }

                packed += fits ? 1 : 0;
                hits += scalar.Intersect ? 1 : 0;
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(seed, trial, new XunitException($"{a} vs {b}: {e.Message}"));
            }
        }

        Assert.InRange(packed, 3000, 16000);
        Assert.InRange(hits, 3000, 15000);
    }

    [Fact]
    public void AxisAlignedAndIntegerPairsAgreeBitForBit()
    {
        // Exact zeros everywhere: axis-aligned normals (with −0 components), integer corners,
        // shared edges, identical shapes, a shape on another's first vertex (the origin of the
        // relative coordinates), quarter turns. Zero signs are where a careless rewrite differs.
        var rng = new Random(1012);
        int hits = 0;
        for (int trial = 0; trial < 20000; trial++)
        {
            try
            {
                var a = IntegerPolygon(rng);
                var b = rng.Next(10) == 0 ? a : IntegerPolygon(rng);
                var viewA = a.View();
                var viewB = b.View();
                var scalar = ConvexSat.Detect(viewA, viewB, vector: false);
                AssertSame(scalar, ConvexSatLanes.Detect(viewA, viewB));
                AssertSame(scalar, ConvexSat.Detect(viewA, viewB));
                var circle = new Circle(b.Vertices[rng.Next(b.Vertices.Length)] + new Vector2(rng.Next(-3, 4), rng.Next(-3, 4)), rng.Next(1, 12));
                AssertSame(scalar, CollisionDetector.Detect(a, b));
                var circleScalar = CircleConvex.Detect(circle, viewA, vector: false);
                AssertSame(circleScalar, CircleConvex.Detect(circle, viewA));
                AssertSame(circleScalar, CollisionDetector.Detect(circle, a));
                hits += scalar.Intersect ? 1 : 0;
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(1012, trial, e);
            }
        }

        Assert.InRange(hits, 2000, 19000);
    }

    // A small polygon on the integer grid: an axis-aligned rectangle, a quarter-turned triangle or
    // a diamond, 3 to 8 vertices, within ±12.
    private static ConvexPolygon IntegerPolygon(Random rng)
    {
        int x = rng.Next(-6, 7), z = rng.Next(-6, 7), w = rng.Next(1, 7), h = rng.Next(1, 7);
        Vector2[] v = rng.Next(4) switch
        {
            0 => [new(x, z), new(x + w, z), new(x + w, z + h), new(x, z + h)],
            1 => [new(x, z), new(x + w, z), new(x, z + h)],
            2 => [new(x, z - h), new(x + w, z), new(x, z + h), new(x - w, z)],
            _ => [new(x, z), new(x + w, z), new(x + w + 1, z + 1), new(x + w + 1, z + h + 1), new(x + w, z + h + 2), new(x, z + h + 2), new(x - 1, z + h + 1), new(x - 1, z + 1)],
        };
        if (rng.Next(2) == 0)
        {
            Array.Reverse(v);
        }

        return new ConvexPolygon(v);
    }

    // The vertices and normals of any polygon-like shape, copied out of its view.
    private static (Vector2[] Vertices, Vector2[] Normals) Outline(Shape shape)
    {
        switch (shape.Kind)
        {
            case ShapeKind.Polygon:
                var polygon = shape.AsPolygon();
                return (polygon.Vertices.ToArray(), polygon.Normals.ToArray());
            case ShapeKind.KDop8:
                var kdop = shape.AsKDop8();
                var view = kdop.View();
                return (view.Vertices.ToArray(), view.Normals.ToArray());
            case ShapeKind.Aabb:
                var corners = new Vector2[4];
                shape.AsAabb().WriteVertices(corners);
                return (corners, Aabb.View(corners).Normals.ToArray());
            default:
                var ends = new Vector2[2];
                var normals = new Vector2[2];
                shape.AsSegment().WriteView(ends, normals);
                return (ends, normals);
        }
    }

    private static void AssertSame(in CollisionDetectionResult expected, in CollisionDetectionResult actual) => BitExact.AssertSame(expected, actual);

    private static void AssertSame(in ContactDepth expected, in ContactDepth actual)
    {
        BitExact.AssertSame(new Vector3(expected.Normal, expected.Depth), new Vector3(actual.Normal, actual.Depth), "normal and depth");
        Assert.Equal((expected.FaceA, expected.FaceB), (actual.FaceA, actual.FaceB));
        BitExact.AssertSame(new Vector3(expected.SeparationA, expected.SeparationB, 0f), new Vector3(actual.SeparationA, actual.SeparationB, 0f), "separations");
    }
}
