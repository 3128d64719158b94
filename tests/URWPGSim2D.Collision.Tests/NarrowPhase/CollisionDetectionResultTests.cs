namespace URWPGSim2D.Collision.Tests.NarrowPhase;

public sealed class CollisionDetectionResultTests
{
    [Fact]
    public void ConstructorForcesYToZero()
    {
        var r = new CollisionDetectionResult(true, new(3, 7, 4), new(0.6f, 1, 0.8f), new(1, 2, 3));
        Assert.Equal(new Vector3(3, 0, 4), r.MinimumTranslationVector);
        Assert.Equal(new Vector3(0.6f, 0, 0.8f), r.NormalAxis);
        Assert.Equal(new Vector3(1, 0, 3), r.ActionPoint);
        Assert.Equal(5f, r.Depth);
    }

    [Fact]
    public void NoneIsDefaultAndAllZero()
    {
        Assert.Equal(default, CollisionDetectionResult.None);
        Assert.False(CollisionDetectionResult.None.Intersect);
        Assert.Equal(0f, CollisionDetectionResult.None.Depth);
        Assert.Equal("Apart", CollisionDetectionResult.None.ToString());
    }

    [Fact]
    public void SwappedNegatesTranslationAndNormalAndKeepsThePoint()
    {
        var r = new CollisionDetectionResult(true, new(3, 0, 4), new(0.6f, 0, 0.8f), new(1, 0, 2));
        var s = r.Swapped();
        Assert.Equal(new Vector3(-3, 0, -4), s.MinimumTranslationVector);
        Assert.Equal(new Vector3(-0.6f, 0, -0.8f), s.NormalAxis);
        Assert.Equal(r.ActionPoint, s.ActionPoint);
        Assert.Equal(r, s.Swapped());
        Assert.Equal(CollisionDetectionResult.None, CollisionDetectionResult.None.Swapped());
    }

    [Fact]
    public void EqualityComparesEveryPart()
    {
        var r = new CollisionDetectionResult(true, new(3, 0, 4), new(0.6f, 0, 0.8f), new(1, 0, 2));
        Assert.True(r == new CollisionDetectionResult(true, new(3, 0, 4), new(0.6f, 0, 0.8f), new(1, 0, 2)));
        Assert.True(r != new CollisionDetectionResult(true, new(3, 0, 4), new(0.6f, 0, 0.8f), new(1, 0, 2.5f)));
        Assert.True(r != new CollisionDetectionResult(false, new(3, 0, 4), new(0.6f, 0, 0.8f), new(1, 0, 2)));
        Assert.False(r.Equals((object)"not a result"));
        Assert.Equal(r.GetHashCode(), new CollisionDetectionResult(true, new(3, 0, 4), new(0.6f, 0, 0.8f), new(1, 0, 2)).GetHashCode());
    }
}
