namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>The one heading wrap: range, identity in range, same direction, whole turns removed.</summary>
public sealed class AngleTests
{
    [Theory]
    [InlineData(0f, 0f)]
    [InlineData(-MathF.PI, -MathF.PI)]
    [InlineData(MathF.PI, -MathF.PI)]
    [InlineData(3f * MathF.PI / 2f, -MathF.PI / 2f)]
    [InlineData(-3f * MathF.PI / 2f, MathF.PI / 2f)]
    public void KnownAngles(float angle, float wrapped) => Assert.Equal(wrapped, Angle.Wrap(angle), 1e-5f);

    [Fact]
    public void AnAngleInRangeIsReturnedBitForBit()
    {
        var random = new Random(23);
        for (int i = 0; i < 10_000; i++)
        {
            float a = (float)((random.NextDouble() * 2.0 * Math.PI) - Math.PI);
            if (a < MathF.PI)
            {
                Assert.Equal(BitConverter.SingleToInt32Bits(a), BitConverter.SingleToInt32Bits(Angle.Wrap(a)));
            }
        }
    }

    [Fact]
    public void AnyAngleLandsInRangeFacingTheSameWay()
    {
        var random = new Random(7);
        for (int i = 0; i < 10_000; i++)
        {
            int turns = random.Next(-50, 51);
            double within = (random.NextDouble() * 2.0 * Math.PI) - Math.PI;
            float a = (float)(within + (turns * 2.0 * Math.PI));
            float w = Angle.Wrap(a);
            Assert.InRange(w, -MathF.PI, MathF.PI);
            Assert.True(w < MathF.PI, $"{a} wrapped to {w}");

            // Same direction (within float rounding of the input, which grows with the turns).
            double tolerance = 1e-5 * (1 + Math.Abs(turns));
            Assert.Equal(Math.Cos(a), Math.Cos(w), tolerance);
            Assert.Equal(Math.Sin(a), Math.Sin(w), tolerance);
        }
    }
}
