namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class FloatSlabsTests
{
    private static readonly double Half = Math.Sqrt(0.5);

    [Fact]
    public void VectorAndScalarPathsAgree()
    {
        var rng = new Random(72);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                var points = new Vector2[rng.Next(1, 12)];
                for (int i = 0; i < points.Length; i++)
                {
                    points[i] = new Vector2((float)((rng.NextDouble() * 3000) - 1500), (float)((rng.NextDouble() * 3000) - 1500));
                }

                FloatSlabs.Of(points, out Vector4 min, out Vector4 max);
                FloatSlabs.OfScalar(points, out Vector4 scalarMin, out Vector4 scalarMax);
                Assert.Equal(scalarMin, min);
                Assert.Equal(scalarMax, max);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(72, trial, e);
            }
        }
    }

    [Fact]
    public void EveryPointIsInsideAndTheDiagonalPadIsAFewFloatSteps()
    {
        var rng = new Random(71);
        for (int trial = 0; trial < 5000; trial++)
        {
            try
            {
                int n = rng.Next(1, 9);
                float spread = trial % 3 == 0 ? 25000f : 300f;
                var points = new Vector2[n];
                for (int i = 0; i < n; i++)
                {
                    points[i] = new Vector2((float)(((rng.NextDouble() * 2) - 1) * spread), (float)(((rng.NextDouble() * 2) - 1) * spread));
                }

                FloatSlabs.Of(points, out Vector4 min, out Vector4 max);
                double lo0 = double.MaxValue, hi0 = double.MinValue, lo1 = double.MaxValue, hi1 = double.MinValue, size = 0;
                var lo = new double[] { double.MaxValue, double.MaxValue, double.MaxValue, double.MaxValue };
                var hi = new double[] { double.MinValue, double.MinValue, double.MinValue, double.MinValue };
                foreach (var p in points)
                {
                    double[] exact = [p.X, p.Y, ((double)p.X + p.Y) * Half, ((double)p.X - p.Y) * Half];
                    for (int k = 0; k < 4; k++)
                    {
                        Assert.True(min[k] <= exact[k] && exact[k] <= max[k], $"trial {trial}: a point projects to {exact[k]} on axis {k}, slab [{min[k]}, {max[k]}]");
                        lo[k] = Math.Min(lo[k], exact[k]);
                        hi[k] = Math.Max(hi[k], exact[k]);
                    }

                    lo0 = Math.Min(lo0, p.X);
                    hi0 = Math.Max(hi0, p.X);
                    lo1 = Math.Min(lo1, p.Y);
                    hi1 = Math.Max(hi1, p.Y);
                }

                size = Math.Max(Math.Abs(lo0), Math.Abs(hi0)) + Math.Max(Math.Abs(lo1), Math.Abs(hi1));
                Assert.Equal(lo0, min.X);
                Assert.Equal(hi0, max.X);
                Assert.Equal(lo1, min.Y);
                Assert.Equal(hi1, max.Y);
                for (int k = 2; k < 4; k++)
                {
                    Assert.True(lo[k] - min[k] <= size * 4e-7, $"trial {trial}: axis {k} lower slab {lo[k] - min[k]} mm loose");
                    Assert.True(max[k] - hi[k] <= size * 4e-7, $"trial {trial}: axis {k} upper slab {max[k] - hi[k]} mm loose");
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(71, trial, e);
            }
        }
    }
}
