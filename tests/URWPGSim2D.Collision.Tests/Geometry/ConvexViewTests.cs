using System.Numerics;
using URWPGSim2D.Collision.Shapes;
using Xunit;

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
    public void PolygonViewUsesItsNormalsAsAxes()
    {
        var view = Triangle.View();
        Assert.Equal(3, view.Vertices.Length);
        Assert.Equal(view.Normals.ToArray(), view.Axes.ToArray());
    }
}
