using Microsoft.Xna.Framework;

namespace URWPGSim2D.Compat.Tests.Xna;

/// <summary>The XNA two-component vector against hand-computed values (against System.Numerics: <see cref="OverloadFamiliesTests"/>).</summary>
public sealed class Vector2Tests
{
    [Fact]
    public void ArithmeticMatchesHandComputedValues()
    {
        var a = new Vector2(1f, -2f);
        var b = new Vector2(4f, 2f);
        Assert.Equal(new Vector2(5f, 0f), Vector2.Add(a, b));
        Assert.Equal(new Vector2(-3f, -4f), Vector2.Subtract(a, b));
        Assert.Equal(new Vector2(4f, -4f), Vector2.Multiply(a, b));
        Assert.Equal(new Vector2(4f, -4f), a * b);
        Assert.Equal(new Vector2(3f, -6f), Vector2.Multiply(a, 3f));
        Assert.Equal(new Vector2(0.25f, -1f), Vector2.Divide(a, b));
        Assert.Equal(new Vector2(0.25f, -1f), a / b);
        Assert.Equal(new Vector2(0.5f, -1f), Vector2.Divide(a, 2f));
        Assert.Equal(new Vector2(-1f, 2f), Vector2.Negate(a));
        Assert.Equal(new Vector2(1f, -2f), Vector2.Min(a, b));
        Assert.Equal(new Vector2(4f, 2f), Vector2.Max(a, b));
        Assert.Equal(new Vector2(1f, 0f), Vector2.Clamp(a, Vector2.Zero, Vector2.One));
        Assert.Equal(new Vector2(3f, 3f), Vector2.Clamp(new Vector2(5f), new Vector2(3f), new Vector2(1f)));
        Assert.Equal(new Vector2(1f, 2f), Vector2.Reflect(new Vector2(1f, -2f), Vector2.UnitY));
    }

    [Fact]
    public void SplinesMatchThePolynomialsTheyReproduce()
    {
        // X samples t² at −1, 0, 1, 2; Y samples the line 2t + 1.
        var mid = Vector2.CatmullRom(new Vector2(1f, -1f), new Vector2(0f, 1f), new Vector2(1f, 3f), new Vector2(4f, 5f), 0.5f);
        Assert.Equal(0.25f, mid.X, 6);
        Assert.Equal(2f, mid.Y, 6);
        // X follows t³ (slopes 0 and 3), Y stays at 7.
        var h = Vector2.Hermite(new Vector2(0f, 7f), Vector2.Zero, new Vector2(1f, 7f), new Vector2(3f, 0f), 0.5f);
        Assert.Equal(0.125f, h.X, 6);
        Assert.Equal(7f, h.Y, 6);
        Assert.Equal(new Vector2(2f, 2.5f), Vector2.Barycentric(new Vector2(1f, 2f), new Vector2(3f, 4f), new Vector2(1f, 0f), 0.5f, 0.25f));
        Assert.Equal(new Vector2(1.5625f, -1.5625f), Vector2.SmoothStep(Vector2.Zero, new Vector2(10f, -10f), 0.25f));
        Assert.Equal(Vector2.Zero, Vector2.SmoothStep(Vector2.Zero, new Vector2(10f, -10f), -1f));
    }
}
