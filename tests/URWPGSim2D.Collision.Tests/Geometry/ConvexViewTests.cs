namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class ConvexViewTests
{
    private static readonly ConvexPolygon Triangle = new([new(0, 0), new(10, 0), new(2, 6)]);

    [Fact]
    public void ProjectGivesTheIntervalRelativeToTheOrigin()
    {
        var view = Triangle.View();
        view.Project(new(1, 0), new(5, 5), out float min, out float max);
        Assert.Equal(-5f, min);
        Assert.Equal(5f, max);
        view.Project(new(0, 1), Vector2.Zero, out min, out max);
        Assert.Equal(0f, min);
        Assert.Equal(6f, max);
    }

    [Fact]
    public void SupportIsTheFarthestVertex()
    {
        var view = Triangle.View();
        Assert.Equal(new Vector2(10, 0), view.Support(new(1, 0)));
        Assert.Equal(new Vector2(2, 6), view.Support(new(0, 1)));
        Assert.Equal(new Vector2(0, 0), view.Support(new(-1, -1)));
    }

    [Fact]
    public void PolygonViewHasOneOutwardUnitNormalPerEdge()
    {
        var view = Triangle.View();
        Assert.Equal(3, view.Vertices.Length);
        Assert.Equal(3, view.Normals.Length);
        for (int i = 0; i < 3; i++)
        {
            Vector2 edge = view.Vertices[(i + 1) % 3] - view.Vertices[i];
            Assert.Equal(1f, view.Normals[i].Length(), 1e-6f);
            Assert.Equal(0f, Vector2.Dot(view.Normals[i], edge), 1e-5f);
            Assert.True(Vector2.Dot(view.Normals[i], view.Vertices[(i + 2) % 3] - view.Vertices[i]) < 0f, "normal points outward");
        }
    }
}
