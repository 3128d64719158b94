namespace URWPGSim2D.Collision.Tests.Shapes;

public sealed class AabbTests
{
    [Fact]
    public void NonFiniteCornersAreRejected()
    {
        ArgumentAssert.Throws("min", () => _ = new Aabb(new(float.NaN, 0), new(1, 1)), "finite", "NaN");
        ArgumentAssert.Throws("max", () => _ = new Aabb(new(0, 0), new(1, float.PositiveInfinity)), "finite", "Infinity");
    }

    [Fact]
    public void MinGreaterThanMaxIsRejectedNamingTheValues()
    {
        ArgumentAssert.Throws("min", () => _ = new Aabb(new(5, 0), new(3, 1)), "min x", "5", "max x", "3");
        ArgumentAssert.Throws("min", () => _ = new Aabb(new(0, 7.5f), new(1, -2)), "min z", "7.5", "max z", "-2");
    }

    [Fact]
    public void FlatAndPointBoxesAreAllowed()
    {
        var flat = new Aabb(new(0, 3), new(10, 3));
        Assert.Equal(new Vector2(5, 3), flat.Center);
        var point = new Aabb(new(2, 2), new(2, 2));
        Assert.Equal(0f, point.BoundingCircle.Radius);
    }

    [Fact]
    public void BoundingCirclePassesThroughTheCorners()
    {
        var box = new Aabb(new(0, 0), new(6, 8));
        Assert.Equal(new Vector2(3, 4), box.BoundingCircle.Center);
        Assert.Equal(5f, box.BoundingCircle.Radius);
    }

    [Fact]
    public void OverlapsIsStrictAndTranslatedMovesBothCorners()
    {
        var box = new Aabb(new(0, 0), new(10, 10));
        Assert.True(box.Overlaps(new Aabb(new(9, 9), new(12, 12))));
        Assert.False(box.Overlaps(new Aabb(new(10, 0), new(12, 12))));
        var moved = box.Translated(new(1, -1));
        Assert.Equal(new Vector2(1, -1), moved.Min);
        Assert.Equal(new Vector2(11, 9), moved.Max);
    }
}
