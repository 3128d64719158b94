using System.Numerics;
using URWPGSim2D.Collision.Geometry;
using Xunit;

namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class XZPlaneTests
{
    [Fact]
    public void WorldAndPlaneVectorsMapXAndZ()
    {
        Assert.Equal(new Vector3(3, 0, -4), XZPlane.ToWorld(new(3, -4)));
        Assert.Equal(new Vector2(3, -4), XZPlane.ToPlane(new(3, 99, -4)));
    }

    [Fact]
    public void CrossIsTheSignedParallelogramArea()
    {
        Assert.Equal(1f, XZPlane.Cross(new(1, 0), new(0, 1)));
        Assert.Equal(-1f, XZPlane.Cross(new(0, 1), new(1, 0)));
        Assert.Equal(0f, XZPlane.Cross(new(2, 4), new(1, 2)));
    }

    [Fact]
    public void RightPerpIsTheOutwardNormalOfACounterClockwiseEdge()
    {
        // Square (0,0), (1,0), (1,1), (0,1) has positive signed area: its bottom edge faces −z.
        Assert.Equal(new Vector2(0, -1), XZPlane.RightPerp(new(1, 0)));
        Assert.Equal(new Vector2(1, 0), XZPlane.RightPerp(new(0, 1)));
    }
}
