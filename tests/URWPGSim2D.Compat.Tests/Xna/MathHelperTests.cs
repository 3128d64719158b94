using Microsoft.Xna.Framework;

namespace URWPGSim2D.Compat.Tests.Xna;

/// <summary>MathHelper against hand-computed values.</summary>
public sealed class MathHelperTests
{
    [Theory]
    [InlineData(0.0, 0.0)]
    [InlineData(Math.PI * 1.5, -Math.PI / 2)]
    [InlineData(-Math.PI * 1.5, Math.PI / 2)]
    [InlineData(7.0, 7.0 - (2 * Math.PI))]
    [InlineData(-7.0, -7.0 + (2 * Math.PI))]
    [InlineData(20.0, 20.0 - (6 * Math.PI))]
    public void WrapAngleLandsInMinusPiToPi(double angle, double expected) =>
        Assert.Equal((float)expected, MathHelper.WrapAngle((float)angle), 5);

    [Fact]
    public void WrapAngleKeepsPiAndTurnsMinusPiIntoPi()
    {
        Assert.Equal(MathHelper.Pi, MathHelper.WrapAngle(MathHelper.Pi));
        Assert.Equal(MathHelper.Pi, MathHelper.WrapAngle(-MathHelper.Pi));
    }

    [Fact]
    public void ConstantsAndConversions()
    {
        Assert.Equal((float)Math.PI, MathHelper.Pi);
        Assert.Equal((float)(2 * Math.PI), MathHelper.TwoPi);
        Assert.Equal((float)(Math.PI / 2), MathHelper.PiOver2);
        Assert.Equal((float)(Math.PI / 4), MathHelper.PiOver4);
        Assert.Equal((float)Math.PI, MathHelper.ToRadians(180f), 6);
        Assert.Equal(90f, MathHelper.ToDegrees((float)(Math.PI / 2)), 4);
        Assert.Equal(-30f, MathHelper.ToDegrees(MathHelper.ToRadians(-30f)), 4);
    }

    [Fact]
    public void ClampLerpMinMaxDistance()
    {
        Assert.Equal(3f, MathHelper.Clamp(5f, 0f, 3f));
        Assert.Equal(0f, MathHelper.Clamp(-5f, 0f, 3f));
        Assert.Equal(1.5f, MathHelper.Clamp(1.5f, 0f, 3f));
        Assert.Equal(2.5f, MathHelper.Lerp(2f, 4f, 0.25f));
        Assert.Equal(-1f, MathHelper.Min(-1f, 2f));
        Assert.Equal(2f, MathHelper.Max(-1f, 2f));
        Assert.Equal(3f, MathHelper.Distance(-1f, 2f));
        Assert.Equal(5f, MathHelper.SmoothStep(0f, 10f, 0.5f));
        Assert.Equal(10f, MathHelper.SmoothStep(0f, 10f, 3f));
        Assert.Equal(2f, MathHelper.Barycentric(1f, 2f, 3f, 0.5f, 0.25f));
    }

    [Fact]
    public void CatmullRomPassesThroughTheInnerPointsAndReproducesQuadratics()
    {
        // Equally spaced samples of f(t) = t² at t = −1, 0, 1, 2: a uniform Catmull-Rom segment
        // reproduces polynomials up to degree 2 exactly, so the curve is t² between 0 and 1.
        Assert.Equal(0f, MathHelper.CatmullRom(1f, 0f, 1f, 4f, 0f));
        Assert.Equal(1f, MathHelper.CatmullRom(1f, 0f, 1f, 4f, 1f));
        Assert.Equal(0.25f, MathHelper.CatmullRom(1f, 0f, 1f, 4f, 0.5f), 6);
        Assert.Equal(0.0625f, MathHelper.CatmullRom(1f, 0f, 1f, 4f, 0.25f), 6);
        // Samples of a line give the line, even outside 0..1 (not clamped).
        Assert.Equal(3.5f, MathHelper.CatmullRom(0f, 1f, 2f, 3f, 2.5f), 5);
    }

    [Fact]
    public void HermiteMatchesTheCubicWithTheGivenEndValuesAndSlopes()
    {
        // f(t) = t³: f(0) = 0, f'(0) = 0, f(1) = 1, f'(1) = 3.
        Assert.Equal(0.125f, MathHelper.Hermite(0f, 0f, 1f, 3f, 0.5f), 6);
        Assert.Equal(0.027f, MathHelper.Hermite(0f, 0f, 1f, 3f, 0.3f), 6);
        // g(t) = 2 − t + 4t² − t³: g(0) = 2, g'(0) = −1, g(1) = 4, g'(1) = 4.
        Assert.Equal(2f - 0.25f + 0.25f - 0.015625f, MathHelper.Hermite(2f, -1f, 4f, 4f, 0.25f), 5);
        Assert.Equal(2f, MathHelper.Hermite(2f, -1f, 4f, 4f, 0f));
        Assert.Equal(4f, MathHelper.Hermite(2f, -1f, 4f, 4f, 1f), 6);
    }
}
