using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class PolygonLanesTests
{
    [Theory]
    [InlineData(3)]
    [InlineData(4)]
    [InlineData(5)]
    [InlineData(6)]
    [InlineData(7)]
    [InlineData(8)]
    public void EveryLaneHoldsItsVertexNormalAndNextVertex(int count)
    {
        var polygon = Regular(count, new Vector2(-12000f, 7000f), 40f);
        var packed = polygon.Lanes!;
        Assert.Equal(PolygonLanes.PackedLength, packed.Length);
        Assert.Equal(count, PolygonLanes.Count(ref MemoryMarshal.GetArrayDataReference(packed)));
        var seen = new bool[count];
        for (int lane = 0; lane < 8; lane++)
        {
            int index = PolygonLanes.Index(lane, count);
            seen[index] = true;
            Assert.Equal(polygon.Vertices[index], new Vector2(packed[lane], packed[8 + lane]));
            Assert.Equal(polygon.Normals[index], new Vector2(packed[16 + lane], packed[24 + lane]));
            Assert.Equal(polygon.Vertices[(index + 1) % count], new Vector2(packed[32 + lane], packed[40 + lane]));
        }

        Assert.All(seen, Assert.True);
        for (int index = 0; index < count; index++)
        {
            Assert.Equal(index, PolygonLanes.Index(PolygonLanes.Lane(index, count), count));
        }

        // The lowest lane holding a repeated index is the lowest lane of that index.
        for (int lane = 1; lane < 8; lane++)
        {
            for (int earlier = 0; earlier < lane; earlier++)
            {
                Assert.True(PolygonLanes.Index(earlier, count) <= PolygonLanes.Index(lane, count) || PolygonLanes.Index(earlier, count) != PolygonLanes.Index(lane, count));
            }
        }
    }

    [Theory]
    [InlineData(3)]
    [InlineData(4)]
    [InlineData(5)]
    [InlineData(8)]
    public void AViewStoresTheSameLanesAsThePolygonPacks(int count)
    {
        if (!PolygonLanes.IsSupported)
        {
            return;
        }

        var polygon = Regular(count, new Vector2(3f, -4f), 700f);
        var stored = new float[PolygonLanes.PackedLength];
        PolygonLanes.Store(polygon.Vertices, polygon.Normals, ref MemoryMarshal.GetArrayDataReference(stored));
        Assert.Equal(polygon.Lanes!, stored);
    }

    [Fact]
    public void LargerPolygonsAreNotPacked()
    {
        Assert.Null(Regular(9, Vector2.Zero, 10f).Lanes);
        Assert.False(PolygonLanes.Fits(2));
        Assert.False(PolygonLanes.Fits(9));
    }

    private static ConvexPolygon Regular(int count, Vector2 centre, float radius)
    {
        var v = new Vector2[count];
        for (int i = 0; i < count; i++)
        {
            v[i] = centre + (radius * new Vector2(MathF.Cos(0.3f + (i * 2f * MathF.PI / count)), MathF.Sin(0.3f + (i * 2f * MathF.PI / count))));
        }

        return new ConvexPolygon(v);
    }
}
