using System.Runtime.Intrinsics;

namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class ConvexLanesTests
{
    [Theory]
    [InlineData(3)]
    [InlineData(4)]
    [InlineData(5)]
    [InlineData(6)]
    [InlineData(7)]
    [InlineData(8)]
    public void EveryLaneHoldsTheVertexAndNormalOfItsIndex(int count)
    {
        // Vertices on a circle around (100, −50), taken relative to vertex 0.
        var v = new Vector2[count];
        for (int i = 0; i < count; i++)
        {
            v[i] = new Vector2(100f + (40f * MathF.Cos(i * 2f * MathF.PI / count)), -50f + (40f * MathF.Sin(i * 2f * MathF.PI / count)));
        }

        var polygon = new ConvexPolygon(v);
        var view = polygon.View();
        Vector2 origin = view.Vertices[0];
        ConvexLanes.Load(view.Vertices, view.Normals, origin, out var lanes);
        Assert.Equal(count, lanes.Count);
        var seen = new bool[count];
        for (int lane = 0; lane < 8; lane++)
        {
            int index = lanes.Index(lane);
            seen[index] = true;
            var (x, z, nx, nz) = lane < 4
                ? (lanes.X0, lanes.Z0, lanes.NX0, lanes.NZ0)
                : (lanes.X1, lanes.Z1, lanes.NX1, lanes.NZ1);
            Assert.Equal(view.Vertices[index] - origin, new Vector2(x.GetElement(lane & 3), z.GetElement(lane & 3)));
            Assert.Equal(view.Normals[index], new Vector2(nx.GetElement(lane & 3), nz.GetElement(lane & 3)));
        }

        Assert.All(seen, Assert.True);
        for (int index = 0; index < count; index++)
        {
            Assert.Equal(index, lanes.Index(lanes.Lane(index)));
        }
    }

    [Fact]
    public void FirstLaneIsTheLowestLaneHoldingTheValue()
    {
        var group0 = Vector128.Create(3f, 7f, 7f, 1f);
        var group1 = Vector128.Create(7f, 9f, 9f, 2f);
        Assert.Equal(1, ConvexLanes.FirstLane(group0, group1, Vector128.Create(7f)));
        Assert.Equal(5, ConvexLanes.FirstLane(group0, group1, ConvexLanes.Greatest(group0, group1)));
        Assert.Equal(3, ConvexLanes.FirstLane(group0, group1, Vector128.Create(1f)));
        Assert.Equal(9f, ConvexLanes.Greatest(group0, group1).GetElement(2));
    }

    [Fact]
    public void OnlyThreeToEightVerticesFit()
    {
        Assert.False(ConvexLanes.Fits(1));
        Assert.False(ConvexLanes.Fits(2));
        Assert.True(ConvexLanes.Fits(3));
        Assert.True(ConvexLanes.Fits(8));
        Assert.False(ConvexLanes.Fits(9));
        Assert.False(ConvexLanes.Fits(64));
    }
}
