namespace URWPGSim2D.Collision.Tests.Geometry;

public sealed class OctagonCentreTests
{
    // 1 / cos 22.5°: the corners of a regular octagon are this far out relative to its apothem.
    private static readonly double CornerFactor = 1.0 / Math.Cos(Math.PI / 8.0);

    [Fact]
    public void SymmetricShapesAreCentredOnTheirCentre()
    {
        AssertCentre([new(-100f, 7f), new(300f, 7f)], new Vector2(100f, 7f));
        AssertCentre([new(10f, 10f), new(30f, 10f), new(30f, 30f), new(10f, 30f)], new Vector2(20f, 20f));
        var octagon = new Vector2[8];
        for (int i = 0; i < 8; i++)
        {
            octagon[i] = new Vector2(-500f, 900f) + (50f * new Vector2(MathF.Cos(i * MathF.PI / 4f + 0.3f), MathF.Sin(i * MathF.PI / 4f + 0.3f)));
        }

        AssertCentre(octagon, new Vector2(-500f, 900f));
        AssertCentre([new(4f, -2f)], new Vector2(4f, -2f));
    }

    [Fact]
    public void VectorAndScalarPathsAgreeBitForBit()
    {
        var rng = new Random(63);
        for (int trial = 0; trial < 4000; trial++)
        {
            try
            {
                var points = RandomPoints(rng, trial);
                FloatSlabs.Of(points, out Vector4 min, out Vector4 max);
                Assert.Equal(OctagonCentre.OfScalar(min, max), OctagonCentre.OfVector(min, max));
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(63, trial, e);
            }
        }
    }

    [Fact]
    public void FarthestPointIsWithinTheOctagonBoundOfTheSmallestCircle()
    {
        var rng = new Random(61);
        double worst = 0;
        for (int trial = 0; trial < 4000; trial++)
        {
            try
            {
                var points = RandomPoints(rng, trial);
                Vector2 c = Centre(points);
                double farthest = 0;
                foreach (var p in points)
                {
                    farthest = Math.Max(farthest, Distance(p, c));
                }

                double minimum = EnclosingCircle.Minimum(points).Radius;
                double scale = Scale(points);
                Assert.True(farthest <= (minimum * (CornerFactor + 1e-5)) + (1e-6 * scale), $"trial {trial}: farthest {farthest}, minimum circle {minimum}");
                if (minimum > 1e-3 * scale)
                {
                    worst = Math.Max(worst, farthest / minimum);
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(61, trial, e);
            }
        }

        // The bound is reached only by special shapes; random ones come well under it.
        Assert.InRange(worst, 1.0, CornerFactor + 1e-5);
    }

    [Fact]
    public void CentreMinimisesTheEnclosingOctagon()
    {
        // Independent check: a grid search (then a finer one) in double for the least apothem
        // max over the eight directions of (support − e·c); the function is 1-Lipschitz.
        var rng = new Random(62);
        for (int trial = 0; trial < 200; trial++)
        {
            var points = RandomPoints(rng, trial);
            Vector2 c = Centre(points);
            double found = Apothem(points, c.X, c.Y);
            double cx = c.X, cz = c.Y, step = Math.Max(1e-3, Scale(points) / 20.0), best = found;
            for (int level = 0; level < 4; level++, step /= 10.0)
            {
                double bx = cx, bz = cz;
                for (int i = -25; i <= 25; i++)
                {
                    for (int j = -25; j <= 25; j++)
                    {
                        double a = Apothem(points, cx + (i * step), cz + (j * step));
                        if (a < best)
                        {
                            best = a;
                            bx = cx + (i * step);
                            bz = cz + (j * step);
                        }
                    }
                }

                cx = bx;
                cz = bz;
            }

            Assert.True(found <= best + 1e-4 + (1e-5 * Scale(points)), $"trial {trial}: apothem {found} at the centre, {best} by search");
        }
    }

    private static void AssertCentre(Vector2[] points, Vector2 expected)
    {
        Vector2 c = Centre(points);
        Assert.True(Vector2.Distance(c, expected) <= 1e-3f, $"centre ({c.X}, {c.Y}), expected ({expected.X}, {expected.Y})");
    }

    private static Vector2 Centre(Vector2[] points)
    {
        FloatSlabs.Of(points, out Vector4 min, out Vector4 max);
        return OctagonCentre.Of(min, max);
    }

    private static Vector2[] RandomPoints(Random rng, int trial)
    {
        int n = rng.Next(1, 24);
        var points = new Vector2[n];
        Vector2 offset = trial % 5 == 0 ? new Vector2(20000f, -15000f) : Vector2.Zero;
        float angle = (float)(rng.NextDouble() * Math.PI * 2);
        for (int i = 0; i < n; i++)
        {
            float u = (float)((rng.NextDouble() * 2) - 1), v = (float)((rng.NextDouble() * 2) - 1);
            Vector2 local = (trial % 4) switch
            {
                0 => new Vector2(400f * u, 400f * v),                            // a cloud
                1 => new Vector2(400f * u, 0.5f * v),                            // nearly flat
                2 => 200f * new Vector2(MathF.Cos(7f * u), MathF.Sin(7f * u)),   // co-circular
                _ => new Vector2(300f * u, 40f * v * v),                         // a thin crescent
            };
            points[i] = offset + new Vector2((local.X * MathF.Cos(angle)) - (local.Y * MathF.Sin(angle)), (local.X * MathF.Sin(angle)) + (local.Y * MathF.Cos(angle)));
        }

        return points;
    }

    private static double Apothem(Vector2[] points, double cx, double cz)
    {
        double worst = double.NegativeInfinity;
        for (int k = 0; k < 8; k++)
        {
            double ex = Math.Cos(k * Math.PI / 4), ez = Math.Sin(k * Math.PI / 4), support = double.NegativeInfinity;
            foreach (var p in points)
            {
                support = Math.Max(support, (ex * p.X) + (ez * p.Y));
            }

            worst = Math.Max(worst, support - ((ex * cx) + (ez * cz)));
        }

        return worst;
    }

    private static double Distance(Vector2 p, Vector2 c) => Math.Sqrt(((double)p.X - c.X) * ((double)p.X - c.X) + (((double)p.Y - c.Y) * ((double)p.Y - c.Y)));

    private static double Scale(Vector2[] points)
    {
        double s = 0;
        foreach (var p in points)
        {
            s = Math.Max(s, Math.Max(Math.Abs(p.X), Math.Abs(p.Y)));
        }

        return s;
    }
}
