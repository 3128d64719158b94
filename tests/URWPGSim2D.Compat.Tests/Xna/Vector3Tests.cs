using Microsoft.Xna.Framework;

namespace URWPGSim2D.Compat.Tests.Xna;

/// <summary>The XNA vector's semantics against hand-computed values.</summary>
public sealed class Vector3Tests
{
    [Fact]
    public void FieldsAreMutableAndNormalizeChangesTheVectorInPlace()
    {
        var v = new Vector3(3f, 0f, 4f);
        Assert.Equal(5f, v.Length());
        Assert.Equal(25f, v.LengthSquared());
        v.X = 6f;
        v.Z = 8f;
        Assert.Equal(10f, v.Length());
        v.Normalize();
        Assert.Equal(0.6f, v.X, 6);
        Assert.Equal(0f, v.Y);
        Assert.Equal(0.8f, v.Z, 6);
        Assert.Equal(1f, v.Length(), 6);
    }

    [Fact]
    public void NormalizingZeroGivesNaNAsInXna()
    {
        var v = Vector3.Zero;
        v.Normalize();
        Assert.True(float.IsNaN(v.X) && float.IsNaN(v.Y) && float.IsNaN(v.Z));
        Assert.True(float.IsNaN(Vector3.Normalize(Vector3.Zero).X));
    }

    [Fact]
    public void StaticsAndOperatorsMatchHandComputedValues()
    {
        var a = new Vector3(1f, 2f, 3f);
        var b = new Vector3(4f, 6f, 3f);
        Assert.Equal(5f, Vector3.Distance(a, b));
        Assert.Equal(25f, Vector3.DistanceSquared(a, b));
        Assert.Equal(4f + 12f + 9f, Vector3.Dot(a, b));
        Assert.Equal(new Vector3(0f, 0f, 1f), Vector3.Cross(Vector3.UnitX, Vector3.UnitY));
        Assert.Equal(new Vector3((2f * 3f) - (3f * 6f), (3f * 4f) - (1f * 3f), (1f * 6f) - (2f * 4f)), Vector3.Cross(a, b));
        Assert.Equal(new Vector3(1.75f, 3f, 3f), Vector3.Lerp(a, b, 0.25f));
        Assert.Equal(new Vector3(1f, 2f, 3f), Vector3.Min(a, b));
        Assert.Equal(new Vector3(4f, 6f, 3f), Vector3.Max(a, b));
        Assert.Equal(new Vector3(5f, 8f, 6f), a + b);
        Assert.Equal(new Vector3(-3f, -4f, 0f), a - b);
        Assert.Equal(new Vector3(-1f, -2f, -3f), -a);
        Assert.Equal(new Vector3(2f, 4f, 6f), a * 2f);
        Assert.Equal(new Vector3(2f, 4f, 6f), 2f * a);
        Assert.Equal(new Vector3(4f, 12f, 9f), a * b);
        Assert.Equal(new Vector3(0.5f, 1f, 1.5f), a / 2f);
        Assert.Equal(new Vector3(0.25f, 2f / 6f, 1f), a / b);
        Assert.True(a == new Vector3(1f, 2f, 3f));
        Assert.True(a != b);
        Assert.Equal(new Vector3(1f, -1f, 0f), Vector3.Reflect(new Vector3(1f, 1f, 0f), Vector3.UnitY));
        Assert.Equal(new Vector3(1f, 1f, 1f), Vector3.One);
        Assert.Equal(new Vector3(0f, 0f, -1f), Vector3.Forward);
    }

    [Fact]
    public void ConvertsToAndFromSystemNumerics()
    {
        System.Numerics.Vector3 n = new Vector3(1f, 2f, 3f);
        Assert.Equal(new System.Numerics.Vector3(1f, 2f, 3f), n);
        Vector3 x = new System.Numerics.Vector3(-4f, 0f, 5f);
        Assert.Equal(new Vector3(-4f, 0f, 5f), x);
        Assert.Equal(new System.Numerics.Vector2(-4f, 5f), x.ToXZ());
        Assert.Equal(new Vector3(7f, 0f, -2f), Vector3.FromXZ(new System.Numerics.Vector2(7f, -2f)));
    }

    [Fact]
    public void TextIsXnasForm() => Assert.Equal("{X:1 Y:-2.5 Z:3}", new Vector3(1f, -2.5f, 3f).ToString());

    [Fact]
    public void SplinesWorkComponentByComponent()
    {
        var a = new Vector3(1f, 0f, -1f);
        var b = new Vector3(0f, 1f, 0f);
        var c = new Vector3(1f, 2f, 1f);
        var d = new Vector3(4f, 3f, 4f);
        // x and z sample t² at −1, 0, 1, 2 (z shifted by −2 at the ends: not a quadratic, checked against MathHelper); y samples a line.
        var mid = Vector3.CatmullRom(a, b, c, d, 0.5f);
        Assert.Equal(0.25f, mid.X, 6);
        Assert.Equal(1.5f, mid.Y, 6);
        Assert.Equal(MathHelper.CatmullRom(-1f, 0f, 1f, 4f, 0.5f), mid.Z);
        Vector3.CatmullRom(ref a, ref b, ref c, ref d, 0.5f, out var viaRef);
        Assert.Equal(mid, viaRef);

        // t³ on X (tangents 0 and 3), a line on Y, a constant on Z.
        var h = Vector3.Hermite(new Vector3(0f, 1f, 5f), new Vector3(0f, 2f, 0f), new Vector3(1f, 3f, 5f), new Vector3(3f, 2f, 0f), 0.5f);
        Assert.Equal(0.125f, h.X, 6);
        Assert.Equal(2f, h.Y, 6);
        Assert.Equal(5f, h.Z, 6);

        Assert.Equal(new Vector3(2f, 2.5f, 1f), Vector3.Barycentric(new Vector3(1f, 2f, 0f), new Vector3(3f, 4f, 2f), new Vector3(1f, 0f, 0f), 0.5f, 0.25f));
        var smooth = Vector3.SmoothStep(Vector3.Zero, new Vector3(10f, -10f, 2f), 0.25f);
        Assert.Equal(new Vector3(1.5625f, -1.5625f, 0.3125f), smooth);
        Assert.Equal(new Vector3(10f, -10f, 2f), Vector3.SmoothStep(Vector3.Zero, new Vector3(10f, -10f, 2f), 2f));
    }

    [Fact]
    public void ClampLetsTheLowerBoundWinWhenTheBoundsCrossAsXnaDoes()
    {
        Assert.Equal(new Vector3(0f, 5f, 3f), Vector3.Clamp(new Vector3(-1f, 9f, 3f), Vector3.Zero, new Vector3(5f)));
        Assert.Equal(new Vector3(3f), Vector3.Clamp(new Vector3(5f), new Vector3(3f), new Vector3(1f)));
        Assert.Equal(MathHelper.Clamp(5f, 3f, 1f), Vector3.Clamp(new Vector3(5f), new Vector3(3f), new Vector3(1f)).X);
    }
}
