namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class HalfPlaneClipTests
{
    private static readonly Vector2[] Square = [new(0, 0), new(10, 0), new(10, 10), new(0, 10)];

    [Fact]
    public void ClipByAVerticalLineGivesARectangle()
    {
        Span<Vector2> output = stackalloc Vector2[5];
        int n = HalfPlaneClip.Clip(Square, output, new(1, 0), 4);
        Assert.Equal(
            new[] { new Vector2(0, 0), new Vector2(4, 0), new Vector2(4, 10), new Vector2(0, 10) }.OrderBy(p => p.X).ThenBy(p => p.Y),
            output[..n].ToArray().OrderBy(p => p.X).ThenBy(p => p.Y));
    }

    [Fact]
    public void ClipThroughTwoCornersKeepsThemOnceAfterRemovingDuplicates()
    {
        // x + z ≤ 10 passes through (10, 0) and (0, 10): the triangle, with those corners repeated.
        Span<Vector2> output = stackalloc Vector2[5];
        int n = HalfPlaneClip.Clip(Square, output, new(1, 1), 10);
        n = HalfPlaneClip.RemoveNearDuplicates(output, n, 1e-6f);
        Assert.Equal(3, n);
        Assert.Equal(
            new[] { new Vector2(0, 0), new Vector2(10, 0), new Vector2(0, 10) }.OrderBy(p => p.X).ThenBy(p => p.Y),
            output[..n].ToArray().OrderBy(p => p.X).ThenBy(p => p.Y));
    }

    [Fact]
    public void AllInsideIsUnchangedAndAllOutsideIsEmpty()
    {
        Span<Vector2> output = stackalloc Vector2[5];
        Assert.Equal(4, HalfPlaneClip.Clip(Square, output, new(1, 0), 20));
        Assert.Equal(Square, output[..4].ToArray());
        Assert.Equal(0, HalfPlaneClip.Clip(Square, output, new(1, 0), -1));
        Assert.Equal(0, HalfPlaneClip.Clip(ReadOnlySpan<Vector2>.Empty, output, new(1, 0), 0));
    }

    [Fact]
    public void RemoveNearDuplicatesAlsoComparesLastWithFirst()
    {
        Vector2[] v = [new(0, 0), new(0, 1e-7f), new(5, 0), new(5, 5), new(1e-7f, 0)];
        int n = HalfPlaneClip.RemoveNearDuplicates(v, v.Length, 1e-6f);
        Assert.Equal(3, n);
        Assert.Equal([new(0, 0), new(5, 0), new(5, 5)], v[..n]);
    }
}
