namespace URWPGSim2D.Collision.Tests.Shapes;

public sealed class ConvexPolygonTests
{
    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(2)]
    public void FewerThanThreeVerticesAreRejected(int count)
    {
        var v = Enumerable.Range(0, count).Select(i => new Vector2(i, i * i)).ToArray();
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon(v), "at least 3", $"got {count}");
    }

    [Fact]
    public void MoreThanSixtyFourVerticesAreRejectedButSixtyFourAreFine()
    {
        static Vector2[] Regular(int n) =>
            Enumerable.Range(0, n).Select(i => new Vector2(100 * MathF.Cos(i * 2 * MathF.PI / n), 100 * MathF.Sin(i * 2 * MathF.PI / n))).ToArray();
        Assert.Equal(64, new ConvexPolygon(Regular(64)).Vertices.Length);
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon(Regular(65)), "65", "at most 64");
    }

    [Theory]
    [InlineData(float.NaN, "NaN")]
    [InlineData(float.PositiveInfinity, "Infinity")]
    public void NonFiniteVertexIsRejectedNamingItsIndex(float bad, string shown) =>
        ArgumentAssert.Throws("vertices[2]", () => _ = new ConvexPolygon([new(0, 0), new(10, 0), new(10, bad), new(0, 10)]), "finite", shown);

    [Fact]
    public void RepeatedVertexIsRejectedNamingItAndItsIndices()
    {
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon([new(0, 0), new(1, 0), new(1, 0), new(0, 1)]), "repeats vertex", "[1, 0]", "indices 1 and 2");
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon([new(0, 0), new(4, 0), new(4, 4), new(0, 0), new(0, 4)]), "repeats vertex", "[0, 0]", "indices 0 and 3");
    }

    [Fact]
    public void CollinearVerticesAreRejected()
    {
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon([new(0, 0), new(1, 1), new(2, 2)]), "collinear");
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon([new(0, 0), new(3, 0), new(1, 0), new(4, 0), new(2, 0)]), "collinear");
    }

    [Fact]
    public void NonConvexPolygonsAreRejected()
    {
        // A dart (reflex vertex at (3, 5)), a bow-tie (zero net area) and a pentagram (winds twice).
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon([new(0, 0), new(10, 5), new(0, 10), new(3, 5)]), "not convex");
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon([new(0, 0), new(10, 10), new(10, 0), new(0, 10)]), "not convex");
        var star = new[] { 0, 2, 4, 1, 3 }.Select(i => new Vector2(10 * MathF.Cos(i * 2 * MathF.PI / 5), 10 * MathF.Sin(i * 2 * MathF.PI / 5))).ToArray();
        ArgumentAssert.Throws("vertices", () => _ = new ConvexPolygon(star), "not convex");
    }

    [Fact]
    public void EitherWindingIsAcceptedAndStoredCounterClockwiseWithOutwardUnitNormals()
    {
        Vector2[] ccw = [new(0, 0), new(10, 0), new(12, 7), new(3, 9)];
        var clockwise = ccw.Reverse().ToArray();
        foreach (var input in new[] { ccw, clockwise })
        {
            var p = new ConvexPolygon(input);
            Assert.Equal(ccw.OrderBy(v => v.X).ThenBy(v => v.Y), p.Vertices.ToArray().OrderBy(v => v.X).ThenBy(v => v.Y));
            AssertCounterClockwiseWithOutwardNormals(p);
        }
    }

    [Fact]
    public void RedundantCollinearVertexIsAccepted()
    {
        var p = new ConvexPolygon([new(0, 0), new(5, 0), new(10, 0), new(10, 10), new(0, 10)]);
        Assert.Equal(5, p.Vertices.Length);
        AssertCounterClockwiseWithOutwardNormals(p);
    }

    [Fact]
    public void SmallConvexPolygonFarFromTheOriginSurvivesFloatRounding()
    {
        // A 5 mm square with its edge midpoints as extra vertices, rotated and placed near
        // (24000, −24000) in double, then rounded to float: rounding (0.001 mm there) may put a
        // midpoint a hair outside its edge. That is float resolution, not a non-convex polygon.
        for (int degrees = 0; degrees < 180; degrees += 7)
        {
            double angle = degrees * Math.PI / 180;
            var corners = new[] { (-2.5, -2.5), (2.5, -2.5), (2.5, 2.5), (-2.5, 2.5) };
            var outline = corners.SelectMany((c, i) =>
            {
                var n = corners[(i + 1) % 4];
                return new[] { c, ((c.Item1 + n.Item1) / 2, (c.Item2 + n.Item2) / 2) };
            });
            var v = outline.Select(p => new Vector2(
                (float)(24000.3 + p.Item1 * Math.Cos(angle) - p.Item2 * Math.Sin(angle)),
                (float)(-24000.7 + p.Item1 * Math.Sin(angle) + p.Item2 * Math.Cos(angle)))).ToArray();
            var polygon = new ConvexPolygon(v);
            Assert.Equal(8, polygon.Vertices.Length);
        }
    }

    [Fact]
    public void BoundingCircleHoldsEveryVertex()
    {
        var p = new ConvexPolygon([new(0, 0), new(10, 0), new(12, 7), new(3, 9)]);
        foreach (var v in p.Vertices)
        {
            Assert.True(Vector2.Distance(v, p.BoundingCircle.Center) <= p.BoundingCircle.Radius * (1 + 1e-6f));
        }
    }

    [Fact]
    public void TranslatedMovesEveryVertex()
    {
        var p = new ConvexPolygon([new(0, 0), new(10, 0), new(3, 9)]);
        var moved = p.Translated(new(100, -50));
        Assert.Equal(p.Vertices.ToArray().Select(v => v + new Vector2(100, -50)), moved.Vertices.ToArray());
    }

    [Fact]
    public void DefaultPolygonCannotBeTested() =>
        Assert.Throws<InvalidOperationException>(() => CollisionDetector.Detect(default(ConvexPolygon), new Circle(Vector2.Zero, 1)));

    private static void AssertCounterClockwiseWithOutwardNormals(ConvexPolygon p)
    {
        var v = p.Vertices.ToArray().Select(Point2.From).ToArray();
        double area2 = 0;
        for (int i = 0; i < v.Length; i++)
        {
            area2 += Point2.Cross(v[i], v[(i + 1) % v.Length]);
        }

        Assert.True(area2 > 0, "vertices must be counter-clockwise in x–z coordinates (positive signed area)");
        for (int i = 0; i < v.Length; i++)
        {
            Point2 n = Point2.From(p.Normals[i]);
            Point2 edge = v[(i + 1) % v.Length] - v[i];
            Assert.Equal(1, n.Length, 1e-6);
            Assert.Equal(0, Point2.Dot(n, edge) / edge.Length, 1e-6);
            Assert.All(v, q => Assert.True(Point2.Dot(n, q - v[i]) <= 1e-4, $"vertex {q} is outside edge {i}"));
        }
    }
}
