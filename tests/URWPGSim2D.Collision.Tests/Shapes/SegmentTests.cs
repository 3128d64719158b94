namespace URWPGSim2D.Collision.Tests.Shapes;

public sealed class SegmentTests
{
    [Fact]
    public void NonFiniteEndsAreRejected()
    {
        ArgumentAssert.Throws("a", () => _ = new Segment(new(float.NaN, 0), new(1, 1)), "finite", "NaN");
        ArgumentAssert.Throws("b", () => _ = new Segment(new(0, 0), new(float.NegativeInfinity, 1)), "finite", "-Infinity");
    }

    [Fact]
    public void ZeroLengthIsRejectedNamingThePoint() =>
        ArgumentAssert.Throws("b", () => _ = new Segment(new(2.5f, -3), new(2.5f, -3)), "zero length", "2.5", "-3");

    [Fact]
    public void BoundingCircleAndTranslation()
    {
        var s = new Segment(new(0, 0), new(6, 8));
        Assert.Equal(new Vector2(3, 4), s.BoundingCircle.Center);
        Assert.Equal(5f, s.BoundingCircle.Radius);
        var moved = s.Translated(new(1, 1));
        Assert.Equal(new Vector2(1, 1), moved.A);
        Assert.Equal(new Vector2(7, 9), moved.B);
    }
}
