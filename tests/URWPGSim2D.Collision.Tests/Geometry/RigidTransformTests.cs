namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class RigidTransformTests
{
    [Fact]
    public void PlaceAndTurnEqualThePointByPointFormulaBitForBit()
    {
        // The vector path (four points per register, then two) must not change a single bit: every
        // length from 0 to 31 (a fish's 31 leaf vertices, its body group's 13, its tail group's 18)
        // covers the blocks, the overlapping last block and the odd last point.
        var rng = new Random(81);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                int n = trial % 32;
                var local = new Vector2[n];
                for (int i = 0; i < n; i++)
                {
                    local[i] = new Vector2((float)((rng.NextDouble() * 400) - 200), (float)((rng.NextDouble() * 400) - 200));
                }

                (float sin, float cos) = MathF.SinCos((float)(rng.NextDouble() * 20 - 10));
                var rotation = new Vector2(cos, sin);
                var origin = new Vector2((float)((rng.NextDouble() * 50000) - 25000), (float)((rng.NextDouble() * 50000) - 25000));
                var placed = new Vector2[n];
                var turned = new Vector2[n];
                RigidTransform.Place(local, placed, origin, rotation);
                RigidTransform.Turn(local, turned, rotation);
                for (int i = 0; i < n; i++)
                {
                    Vector2 r = new((local[i].X * cos) - (local[i].Y * sin), (local[i].X * sin) + (local[i].Y * cos));
                    Assert.Equal(r, turned[i]);
                    Assert.Equal(origin + r, placed[i]);
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(81, trial, e);
            }
        }
    }

    [Fact]
    public void RotationIsCounterClockwiseInXZCoordinates()
    {
        Vector2[] local = [new(1f, 0f), new(0f, 1f), new(3f, 4f)];
        var world = new Vector2[3];
        RigidTransform.Place(local, world, new Vector2(10f, 20f), new Vector2(0f, 1f));
        Assert.Equal(new Vector2(10f, 21f), world[0]);
        Assert.Equal(new Vector2(9f, 20f), world[1]);
        Assert.Equal(new Vector2(6f, 23f), world[2]);
    }

    [Fact]
    public void ShortDestinationIsRejected()
    {
        var e = Assert.Throws<ArgumentException>(() => RigidTransform.Place(new Vector2[3], new Vector2[2], Vector2.Zero, Vector2.UnitX));
        Assert.Contains("world", e.ParamName);
    }
}
