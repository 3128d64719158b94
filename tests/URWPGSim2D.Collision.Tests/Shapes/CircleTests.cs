namespace URWPGSim2D.Collision.Tests.Shapes;

public sealed class CircleTests
{
    [Theory]
    [InlineData(float.NaN, 0f, "NaN")]
    [InlineData(0f, float.NaN, "NaN")]
    [InlineData(float.PositiveInfinity, 0f, "Infinity")]
    [InlineData(0f, float.NegativeInfinity, "-Infinity")]
    public void NonFiniteCentreIsRejected(float x, float z, string shown) =>
        ArgumentAssert.Throws("center", () => _ = new Circle(new(x, z), 1), "finite", shown);

    [Theory]
    [InlineData(0f, "0")]
    [InlineData(-1f, "-1")]
    [InlineData(-0.001f, "-0.001")]
    public void RadiusMustBePositive(float radius, string shown) =>
        ArgumentAssert.Throws("radius", () => _ = new Circle(Vector2.Zero, radius), "> 0", shown);

    [Theory]
    [InlineData(float.NaN, "NaN")]
    [InlineData(float.PositiveInfinity, "Infinity")]
    public void RadiusMustBeFinite(float radius, string shown) =>
        ArgumentAssert.Throws("radius", () => _ = new Circle(Vector2.Zero, radius), "finite", shown);

    [Fact]
    public void ItsFloatsLieCentreThenRadius()
    {
        // The vector kernels broadcast the centre and the radius straight from the circle.
        var c = new Circle(new(-24999.5f, 3.25f), 0.001f);
        ref float f = ref Circle.Floats(c);
        Assert.Equal(c.Center.X, f);
        Assert.Equal(c.Center.Y, System.Runtime.CompilerServices.Unsafe.Add(ref f, 1));
        Assert.Equal(c.Radius, System.Runtime.CompilerServices.Unsafe.Add(ref f, 2));
    }

    [Fact]
    public void ValidCircleKeepsItsNumbers()
    {
        var c = new Circle(new(-24999.5f, 3), 0.001f);
        Assert.Equal(new Vector2(-24999.5f, 3), c.Center);
        Assert.Equal(0.001f, c.Radius);
        Assert.Equal(c.Center, c.BoundingCircle.Center);
        Assert.Equal(c.Radius, c.BoundingCircle.Radius);
    }

    [Fact]
    public void OverlapsIsStrict()
    {
        var a = new Circle(new(0, 0), 3);
        Assert.True(a.Overlaps(new Circle(new(4.9f, 0), 2)));
        Assert.False(a.Overlaps(new Circle(new(5, 0), 2)));
    }

    [Fact]
    public void TranslatedMovesTheCentre()
    {
        var c = new Circle(new(1, 2), 3).Translated(new(10, -20));
        Assert.Equal(new Vector2(11, -18), c.Center);
        Assert.Equal(3f, c.Radius);
    }
}
