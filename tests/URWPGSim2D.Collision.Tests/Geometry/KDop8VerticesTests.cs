namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class KDop8VerticesTests
{
    [Fact]
    public void EmptyRegionGivesNoVertices()
    {
        Span<Vector2> v = stackalloc Vector2[8];
        Span<Vector2> n = stackalloc Vector2[8];
        Assert.Equal(0, KDop8Vertices.Compute(new(0, 0, 10, -1), new(1, 1, 11, 1), v, n, out _, out _));
    }

    [Fact]
    public void SinglePointFromItsOwnRoundedSlabsIsKept()
    {
        // The diagonal slabs of (24000.25, −17.5) are irrational: rounded outward they still hold it.
        float x = 24000.25f, z = -17.5f;
        double h = Math.Sqrt(0.5);
        var min = new Vector4(x, z, KDop8Vertices.RoundDown((x + (double)z) * h), KDop8Vertices.RoundDown((x - (double)z) * h));
        var max = new Vector4(x, z, KDop8Vertices.RoundUp((x + (double)z) * h), KDop8Vertices.RoundUp((x - (double)z) * h));
        Span<Vector2> v = stackalloc Vector2[8];
        Span<Vector2> n = stackalloc Vector2[8];
        Assert.Equal(1, KDop8Vertices.Compute(min, max, v, n, out _, out _));
        Assert.Equal(new Vector2(x, z), v[0]);
    }

    [Fact]
    public void RoundingDirections()
    {
        double third = 1.0 / 3;
        Assert.True(KDop8Vertices.RoundDown(third) < third && MathF.BitIncrement(KDop8Vertices.RoundDown(third)) > third);
        Assert.True(KDop8Vertices.RoundUp(third) > third && MathF.BitDecrement(KDop8Vertices.RoundUp(third)) < third);
        Assert.Equal(0.5f, KDop8Vertices.RoundDown(0.5));
        Assert.Equal(0.5f, KDop8Vertices.RoundUp(0.5));
    }

    [Fact]
    public void ProjectUsesTheFourAxes()
    {
        Assert.Equal(3, KDop8Vertices.Project(3, 4, 0));
        Assert.Equal(4, KDop8Vertices.Project(3, 4, 1));
        Assert.Equal(7 * Math.Sqrt(0.5), KDop8Vertices.Project(3, 4, 2), 1e-12);
        Assert.Equal(-Math.Sqrt(0.5), KDop8Vertices.Project(3, 4, 3), 1e-12);
    }
}
