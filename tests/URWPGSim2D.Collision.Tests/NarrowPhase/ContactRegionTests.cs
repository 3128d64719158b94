namespace URWPGSim2D.Collision.Tests.NarrowPhase;

public sealed class ContactRegionTests
{
    private static readonly ConvexPolygon Square = new([new(0, 0), new(10, 0), new(10, 10), new(0, 10)]);

    [Fact]
    public void CentroidOfATriangleAndOfADegenerateOutline()
    {
        Assert.Equal(new Vector2(4, 2), ContactRegion.Centroid([new(0, 0), new(9, 0), new(3, 6)]));
        Assert.Equal(new Vector2(5, 5), ContactRegion.Centroid([new(0, 0), new(10, 0), new(10, 10), new(0, 10)]));
        Assert.Equal(new Vector2(2, 0), ContactRegion.Centroid([new(0, 0), new(4, 0), new(2, 0)]));
    }

    [Fact]
    public void LineIntervalThroughASquare()
    {
        ContactRegion.LineInterval(Square.View(), new(-5, 5), new(1, 0), out float lo, out float hi);
        Assert.Equal(5f, lo);
        Assert.Equal(15f, hi);
        ContactRegion.LineInterval(Square.View(), new(-5, 20), new(1, 0), out lo, out hi);
        Assert.True(lo > hi);
    }

    [Fact]
    public void GrazingContactPointIsInTheMiddleOfTheTouchingStretch()
    {
        // a = the square; b = [4, 20] × [−10, 0.0001] just under it. Contact normal (0, 1) from b
        // toward a. The touching stretch is x ∈ [4, 10] on z ∈ [0, 0.0001].
        var b = new ConvexPolygon([new(4, -10), new(20, -10), new(20, 0.0001f), new(4, 0.0001f)]);
        var p = ContactRegion.Grazing(Square.View(), b.View(), new(0, 1), new(0, 0));
        Assert.Equal(7f, p.X, 1e-5f);
        Assert.Equal(0.00005f, p.Y, 1e-6f);

        // The same contact seen from b: the same point.
        var q = ContactRegion.Grazing(b.View(), Square.View(), new(0, -1), new(4, -10));
        Assert.Equal(p.X, q.X, 1e-4f);
        Assert.Equal(p.Y, q.Y, 1e-4f);
    }
}
