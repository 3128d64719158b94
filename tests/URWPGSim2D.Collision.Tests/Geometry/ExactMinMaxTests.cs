namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class ExactMinMaxTests
{
    [Fact]
    public void MinAndMaxHaveMathFsBitsForEveryPairThatIsNotNaN()
    {
        float[] special = [0f, -0f, 1f, -1f, float.PositiveInfinity, float.NegativeInfinity, float.Epsilon, -float.Epsilon, float.MaxValue, float.MinValue];
        foreach (float a in special)
        {
            foreach (float b in special)
            {
                XZPlaneTests.AssertSameBits(MathF.Min(a, b), ExactMinMax.Min(a, b));
                XZPlaneTests.AssertSameBits(MathF.Max(a, b), ExactMinMax.Max(a, b));
            }
        }

        var rng = new Random(1014);
        for (int i = 0; i < 100000; i++)
        {
            float a = XZPlaneTests.Value(rng), b = rng.Next(4) == 0 ? a : XZPlaneTests.Value(rng);
            XZPlaneTests.AssertSameBits(MathF.Min(a, b), ExactMinMax.Min(a, b));
            XZPlaneTests.AssertSameBits(MathF.Max(a, b), ExactMinMax.Max(a, b));
        }
    }
}
