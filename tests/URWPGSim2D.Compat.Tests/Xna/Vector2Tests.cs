using Microsoft.Xna.Framework;
using N = System.Numerics;

namespace URWPGSim2D.Compat.Tests.Xna;

/// <summary>The XNA two-component vector against hand-computed values and System.Numerics.</summary>
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

    [Fact]
    public void RefOverloadsGiveWhatSystemNumericsGives()
    {
        var a = new Vector2(1.5f, -2f);
        var b = new Vector2(-4f, 0.5f);
        var lo = new Vector2(-1f);
        var hi = new Vector2(1f);
        N.Vector2 na = a, nb = b;
        Vector2.Add(ref a, ref b, out var r);
        Assert.Equal((Vector2)(na + nb), r);
        Vector2.Subtract(ref a, ref b, out r);
        Assert.Equal((Vector2)(na - nb), r);
        Vector2.Multiply(ref a, ref b, out r);
        Assert.Equal((Vector2)(na * nb), r);
        Vector2.Multiply(ref a, 2.5f, out r);
        Assert.Equal((Vector2)(na * 2.5f), r);
        Vector2.Divide(ref a, ref b, out r);
        Assert.Equal((Vector2)(na / nb), r);
        Vector2.Divide(ref a, 4f, out r);
        Assert.Equal((Vector2)(na / 4f), r);
        Vector2.Negate(ref a, out r);
        Assert.Equal((Vector2)(-na), r);
        Vector2.Min(ref a, ref b, out r);
        Assert.Equal((Vector2)N.Vector2.Min(na, nb), r);
        Vector2.Max(ref a, ref b, out r);
        Assert.Equal((Vector2)N.Vector2.Max(na, nb), r);
        Vector2.Clamp(ref a, ref lo, ref hi, out r);
        Assert.Equal((Vector2)N.Vector2.Clamp(na, lo, hi), r);
        Vector2.Normalize(ref a, out r);
        AssertClose(N.Vector2.Normalize(na), r);
        Vector2.Reflect(ref a, ref r, out var reflected);
        AssertClose(N.Vector2.Reflect(na, N.Vector2.Normalize(na)), reflected);
        Vector2.Lerp(ref a, ref b, 0.3f, out r);
        AssertClose(N.Vector2.Lerp(na, nb, 0.3f), r);
        Vector2.Distance(ref a, ref b, out float f);
        Assert.Equal(N.Vector2.Distance(na, nb), f, 5);
        Vector2.DistanceSquared(ref a, ref b, out f);
        Assert.Equal(N.Vector2.DistanceSquared(na, nb), f, 5);
        Vector2.Dot(ref a, ref b, out f);
        Assert.Equal(N.Vector2.Dot(na, nb), f);
        var c = Vector2.UnitY;
        var d = Vector2.One;
        Vector2.Barycentric(ref a, ref b, ref c, 0.2f, 0.3f, out r);
        Assert.Equal(Vector2.Barycentric(a, b, c, 0.2f, 0.3f), r);
        Vector2.CatmullRom(ref a, ref b, ref c, ref d, 0.4f, out r);
        Assert.Equal(Vector2.CatmullRom(a, b, c, d, 0.4f), r);
        Vector2.Hermite(ref a, ref b, ref c, ref d, 0.4f, out r);
        Assert.Equal(Vector2.Hermite(a, b, c, d, 0.4f), r);
        Vector2.SmoothStep(ref a, ref b, 0.4f, out r);
        Assert.Equal(Vector2.SmoothStep(a, b, 0.4f), r);
    }

    private static void AssertClose(N.Vector2 expected, Vector2 actual)
    {
        Assert.Equal(expected.X, actual.X, 5);
        Assert.Equal(expected.Y, actual.Y, 5);
    }
}
