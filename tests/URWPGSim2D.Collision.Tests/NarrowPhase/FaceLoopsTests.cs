namespace URWPGSim2D.Collision.Tests.NarrowPhase;

public sealed class FaceLoopsTests
{
    [Fact]
    public void VectorAndScalarSeparationsAgreeBitForBit()
    {
        // Random polygons of 3 to 8 vertices (groups of four, overlapping last groups, repeated
        // lanes), segments (two faces) and points (no faces), overlapping and apart.
        var rng = new Random(91);
        int overlapping = 0;
        for (int trial = 0; trial < 20000; trial++)
        {
            try
            {
                Vector2[] a = Shape(rng, out Vector2[] na), b = Shape(rng, out _);
                bool vector = FaceLoops.GreatestSeparationVector(a, na, b, out int face, out float separation);
                bool scalar = FaceLoops.GreatestSeparationScalar(a, na, b, out int scalarFace, out float scalarSeparation);
                Assert.Equal(scalar, vector);
                if (scalar)
                {
                    overlapping++;
                    Assert.Equal(scalarFace, face);
                    Assert.Equal(scalarSeparation, separation);
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(91, trial, e);
            }
        }

        Assert.InRange(overlapping, 2000, 18000);
    }

    [Fact]
    public void TiesGoToTheFirstFaceInBothPaths()
    {
        // A square against a point at its centre: all four faces tie at −5.
        Vector2[] square = [new(-5f, -5f), new(5f, -5f), new(5f, 5f), new(-5f, 5f)];
        Vector2[] normals = [new(0f, -1f), new(1f, 0f), new(0f, 1f), new(-1f, 0f)];
        Vector2[] centre = [Vector2.Zero];
        Assert.True(FaceLoops.GreatestSeparationVector(square, normals, centre, out int face, out float separation));
        Assert.Equal(0, face);
        Assert.Equal(-5f, separation);
        Assert.Equal(0, FaceLoops.LeastDot(normals, new Vector2(0f, 0f)));
        Assert.Equal(1, FaceLoops.LeastDot([new(1f, 0f), new(-1f, 0f), new(-1f, 0f), new(0f, 1f), new(-1f, 0f)], Vector2.UnitX));
    }

    [Fact]
    public void InsideAndLeastDotMatchTheirDefinitions()
    {
        var rng = new Random(92);
        for (int trial = 0; trial < 20000; trial++)
        {
            try
            {
                Vector2[] a = Shape(rng, out Vector2[] na);
                Vector2 p = new(FishTestKit.Range(rng, -120f, 120f), FishTestKit.Range(rng, -120f, 120f));
                bool inside = true;
                for (int i = 0; i < na.Length; i++)
                {
                    inside &= Vector2.Dot(na[i], p - a[i]) <= 1e-3f;
                }

                Assert.Equal(inside, FaceLoops.Inside(a, na, p, 1e-3f));
                if (na.Length > 0)
                {
                    int least = 0;
                    for (int j = 1; j < na.Length; j++)
                    {
                        least = Vector2.Dot(na[j], p) < Vector2.Dot(na[least], p) ? j : least;
                    }

                    Assert.Equal(least, FaceLoops.LeastDot(na, p));
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(92, trial, e);
            }
        }
    }

    [Fact]
    public void VectorAndScalarLineIntervalsAgreeBitForBit()
    {
        var rng = new Random(94);
        int crossing = 0;
        for (int trial = 0; trial < 20000; trial++)
        {
            try
            {
                Vector2[] a = Shape(rng, out Vector2[] na);
                if (trial % 10 == 0)
                {
                    // An axis-aligned box: lines along x or z are parallel to two of its faces.
                    a = [new(-40f, -30f), new(50f, -30f), new(50f, 20f), new(-40f, 20f)];
                    na = [new(0f, -1f), new(1f, 0f), new(0f, 1f), new(-1f, 0f)];
                }

                if (a.Length < 3)
                {
                    continue;
                }

                Vector2 p = new(FishTestKit.Range(rng, -120f, 120f), FishTestKit.Range(rng, -120f, 120f));
                float angle = trial % 5 == 0 ? rng.Next(4) * MathF.PI / 2f : FishTestKit.Range(rng, 0f, 6.3f);
                Vector2 u = trial % 5 == 0 ? new Vector2(MathF.Round(MathF.Cos(angle)), MathF.Round(MathF.Sin(angle))) : new Vector2(MathF.Cos(angle), MathF.Sin(angle));
                FaceLoops.LineInterval(a, na, p, u, out float lo, out float hi);
                ContactRegion.PolygonLineInterval(a, na, p, u, out float scalarLo, out float scalarHi);
                Assert.Equal(scalarLo, lo);
                Assert.Equal(scalarHi, hi);
                crossing += lo <= hi ? 1 : 0;
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(94, trial, e);
            }
        }

        Assert.InRange(crossing, 1000, 19000);
    }

    [Fact]
    public void DepthThenCompleteEqualsDetect()
    {
        // The deepest-contact queries complete only the winner later; it must be the same answer.
        var rng = new Random(93);
        var f = new FishModel(FishSize.Default, default);
        var g = new FishModel(FishSize.Default, default);
        int hits = 0;
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                f.SetPose(FishTestKit.Pose(rng, MathF.PI, 150f));
                g.SetPose(FishTestKit.Pose(rng, MathF.PI, 150f));
                for (int la = 0; la < 8; la++)
                {
                    for (int lb = 0; lb < 8; lb++)
                    {
                        var full = ConvexSat.Detect(f.LeafView(la), g.LeafView(lb));
                        bool overlap = ConvexSat.Depth(f.LeafView(la), g.LeafView(lb), out ContactDepth depth);
                        Assert.Equal(full.Intersect, overlap);
                        if (overlap)
                        {
                            hits++;
                            Assert.Equal(full, ConvexSat.Complete(f.LeafView(la), g.LeafView(lb), depth));
                            Assert.Equal(full.MinimumTranslationVector.LengthSquared(), depth.MtvLengthSquared);
                        }
                    }
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(93, trial, e);
            }
        }

        Assert.True(hits > 1000, $"only {hits} overlapping leaf pairs");
    }

    // A random convex shape near the origin (counter-clockwise, unit outward normals): a polygon
    // of 3 to 8 vertices on an ellipse, a segment, or a single point.
    private static Vector2[] Shape(Random rng, out Vector2[] normals)
    {
        int kind = rng.Next(10);
        Vector2 c = new(FishTestKit.Range(rng, -60f, 60f), FishTestKit.Range(rng, -60f, 60f));
        if (kind == 0)
        {
            normals = [];
            return [c];
        }

        if (kind == 1)
        {
            Vector2 e = new(FishTestKit.Range(rng, -80f, 80f), FishTestKit.Range(rng, -80f, 80f) + 0.5f);
            Vector2 n = Vector2.Normalize(new Vector2(e.Y, -e.X));
            normals = [n, -n];
            return [c, c + e];
        }

        int count = rng.Next(3, 9);
        var v = new Vector2[count];
        float rx = FishTestKit.Range(rng, 5f, 80f), rz = FishTestKit.Range(rng, 5f, 80f), phase = FishTestKit.Range(rng, 0f, 6.3f);
        for (int i = 0; i < count; i++)
        {
            float angle = phase + (i * 2f * MathF.PI / count);
            v[i] = c + new Vector2(rx * MathF.Cos(angle), rz * MathF.Sin(angle));
        }

        var polygon = new ConvexPolygon(v);
        normals = polygon.Normals.ToArray();
        return polygon.Vertices.ToArray();
    }
}
