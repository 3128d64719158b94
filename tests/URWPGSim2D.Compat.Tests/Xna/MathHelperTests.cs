using System;
using Microsoft.Xna.Framework;
using Xunit;

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
}
