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

    [Fact]
    public void DotHasVector2DotsBitsZeroSignsIncluded()
    {
        // Signed zeros, products that cancel exactly, and random values of every magnitude.
        float[] special = [0f, -0f, 1f, -1f, 2.5f, -2.5f, 1e-30f, -1e-30f, 3e30f];
        foreach (float ax in special)
        {
            foreach (float ay in special)
            {
                foreach (float bx in special)
                {
                    foreach (float by in special)
                    {
                        AssertSameBits(Vector2.Dot(new(ax, ay), new(bx, by)), XZPlane.Dot(new(ax, ay), new(bx, by)));
                    }
                }
            }
        }

        var rng = new Random(1013);
        for (int i = 0; i < 100000; i++)
        {
            Vector2 a = new(Value(rng), Value(rng)), b = new(Value(rng), Value(rng));
            AssertSameBits(Vector2.Dot(a, b), XZPlane.Dot(a, b));
        }
    }

    // A float of random sign and magnitude (10⁻⁸ to 10⁸), sometimes ±0 or an integer.
    internal static float Value(Random rng) => rng.Next(8) switch
    {
        0 => rng.Next(2) == 0 ? 0f : -0f,
        1 => rng.Next(-5, 6),
        _ => (rng.Next(2) == 0 ? 1 : -1) * MathF.Pow(10, (16 * rng.NextSingle()) - 8),
    };

    internal static void AssertSameBits(float expected, float actual) =>
        Assert.Equal(BitConverter.SingleToInt32Bits(expected).ToString("X8"), BitConverter.SingleToInt32Bits(actual).ToString("X8"));
}
