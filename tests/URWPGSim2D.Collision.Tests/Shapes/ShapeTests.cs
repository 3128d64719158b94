namespace URWPGSim2D.Collision.Tests.Shapes;

/// <summary>The <see cref="Shape"/> union: kind, access, and a bounding circle that holds the shape.</summary>
public sealed class ShapeTests
{
    [Fact]
    public void EachShapeConvertsWithItsKind()
    {
        Assert.Equal(ShapeKind.Circle, ((Shape)new Circle(Vector2.Zero, 1)).Kind);
        Assert.Equal(ShapeKind.Aabb, ((Shape)new Aabb(Vector2.Zero, Vector2.One)).Kind);
        Assert.Equal(ShapeKind.KDop8, ((Shape)KDop8.FromPoints([Vector2.Zero])).Kind);
        Assert.Equal(ShapeKind.Polygon, ((Shape)new ConvexPolygon([new(0, 0), new(1, 0), new(0, 1)])).Kind);
        Assert.Equal(ShapeKind.Segment, ((Shape)new Segment(Vector2.Zero, Vector2.One)).Kind);
    }

    [Fact]
    public void AskingForTheWrongKindThrows()
    {
        Shape circle = new Circle(new(1, 2), 3);
        Assert.Equal(3f, circle.AsCircle().Radius);
        var e = Assert.Throws<InvalidOperationException>(() => circle.AsPolygon());
        Assert.Contains("Circle", e.Message, StringComparison.Ordinal);
        Assert.Contains("Polygon", e.Message, StringComparison.Ordinal);
        Assert.Throws<InvalidOperationException>(() => circle.AsAabb());
        Assert.Throws<InvalidOperationException>(() => circle.AsKDop8());
        Assert.Throws<InvalidOperationException>(() => circle.AsSegment());
        Assert.Throws<InvalidOperationException>(() => ((Shape)new Segment(Vector2.Zero, Vector2.One)).AsCircle());
    }

    [Theory]
    [InlineData(ShapeKind.Circle)]
    [InlineData(ShapeKind.Aabb)]
    [InlineData(ShapeKind.KDop8)]
    [InlineData(ShapeKind.Polygon)]
    [InlineData(ShapeKind.Segment)]
    public void BoundingCircleHoldsTheWholeShape(ShapeKind kind)
    {
        var gen = new RandomShapes(1000 + (int)kind);
        for (int i = 0; i < 500; i++)
        {
            var s = gen.Create(kind, new(gen.Uniform(-24000, 24000), gen.Uniform(-24000, 24000)), gen.Size());
            Circle bound = s.Shape.BoundingCircle;
            Point2 c = Point2.From(bound.Center);

            // Farthest point of the reference shape from the circle's centre.
            double far = s.Reference.Core.Max(p => Point2.Distance(p, c)) + s.Reference.Radius;
            Assert.True(far <= bound.Radius + 2e-3, $"{s}: reaches {far:R} mm from the centre, bounding radius {bound.Radius:R}");
        }
    }
}
