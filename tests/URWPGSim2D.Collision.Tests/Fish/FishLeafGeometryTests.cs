namespace URWPGSim2D.Collision.Tests.Fish;

public class FishLeafGeometryTests
{
    // The reference's worked example: deployed sizes, P = (0, 0), θ = 0, all φ = 0, world (X, Z).
    private static readonly Vector2[][] WorkedExample =
    [
        [new(-46.667f, -60f), new(-46.667f, -47.5f), new(-13.333f, -22.5f), new(40f, -22.5f)],
        [new(80f, -22.5f), new(110f, 0f), new(80f, 22.5f), new(-80f, 22.5f), new(-80f, -22.5f)],
        [new(-46.667f, 60f), new(-46.667f, 47.5f), new(-13.333f, 22.5f), new(40f, 22.5f)],
        [new(-80f, 23.418f), new(-80f, -23.418f), new(-168f, -19.302f), new(-168f, 19.302f)],
        [new(-168f, 15.268f), new(-168f, -15.268f), new(-234f, -9.896f), new(-234f, 9.896f)],
        [new(-234f, 6.362f), new(-234f, -6.362f), new(-289f, -4.948f), new(-289f, 4.948f)],
        [new(-344f, -50f), new(-333f, -10f), new(-289f, 4.948f)],
        [new(-333f, 35f), new(-333f, -10f), new(-289f, -4.948f)],
    ];

    [Fact]
    public void WorkedExampleAtHeadingZeroMatchesEveryVertex()
    {
        var fish = new FishModel(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        foreach (var part in FishTestKit.AllParts)
        {
            var leaf = fish.GetLeaf(part);
            var expected = WorkedExample[(int)part];
            Assert.Equal(expected.Length, leaf.Length);
            AssertSameCycle(expected, leaf.ToArray(), 1e-3f, part.ToString());
            Assert.True(ConvexPolygon.SignedArea2(leaf) > 0f, $"{part} is not counter-clockwise");
        }
    }

    [Fact]
    public void LeavesFollowTheReferenceFormulasAtRandomPoses()
    {
        var rng = new Random(11);
        for (int trial = 0; trial < 2000; trial++)
        {
            var size = trial % 4 == 0 ? FishTestKit.Size(rng) : FishSize.Default;
            var pose = FishTestKit.Pose(rng, spread: 1500f);
            var fish = new FishModel(size, pose);
            var expected = ReferenceLeaves(size, pose);
            foreach (var part in FishTestKit.AllParts)
            {
                AssertSameCycle(expected[(int)part], fish.GetLeaf(part).ToArray(), 2e-3f, $"trial {trial} {part}");
                Assert.True(ConvexPolygon.SignedArea2(fish.GetLeaf(part)) > 0f, $"trial {trial}: {part} is not counter-clockwise");
            }
        }
    }

    [Fact]
    public void EveryPoseIsTheHeadingZeroPoseRotatedAndMoved()
    {
        var rng = new Random(12);
        var fish = new FishModel(FishSize.Default, default);
        var straight = new FishModel(FishSize.Default, default);
        for (int trial = 0; trial < 2000; trial++)
        {
            var pose = FishTestKit.Pose(rng, spread: 1500f);
            fish.SetPose(pose);
            straight.SetPose(new FishPose(Vector2.Zero, 0f, pose.Joint1, pose.Joint2, pose.Joint3));
            double c = Math.Cos(pose.Heading), s = Math.Sin(pose.Heading);
            foreach (var part in FishTestKit.AllParts)
            {
                var moved = fish.GetLeaf(part);
                var at0 = straight.GetLeaf(part);
                for (int i = 0; i < moved.Length; i++)
                {
                    double x = pose.Position.X + (at0[i].X * c) - (at0[i].Y * s);
                    double z = pose.Position.Y + (at0[i].X * s) + (at0[i].Y * c);
                    Assert.True(Math.Abs(moved[i].X - x) < 2e-3 && Math.Abs(moved[i].Y - z) < 2e-3, $"trial {trial} {part}[{i}]: ({moved[i].X}, {moved[i].Y}) vs ({x}, {z})");
                }
            }
        }
    }

    [Fact]
    public void LeavesAreRigidAtEveryPose()
    {
        // Edge lengths and turning angles of each leaf, and the distances from the caudal fin to
        // tail segment 3, are those of the worked example whatever the pose: no |cos θ| scaling.
        var rng = new Random(13);
        var reference = new FishModel(FishSize.Default, default);
        var fish = new FishModel(FishSize.Default, default);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                var pose = FishTestKit.Pose(rng, spread: 1500f);
                fish.SetPose(pose);
                reference.SetPose(new FishPose(Vector2.Zero, 0f, pose.Joint1, pose.Joint2, pose.Joint3));
                foreach (var part in FishTestKit.AllParts)
                {
                    var a = fish.GetLeaf(part);
                    var b = reference.GetLeaf(part);
                    for (int i = 0; i < a.Length; i++)
                    {
                        Vector2 ea = a[(i + 1) % a.Length] - a[i], eb = b[(i + 1) % b.Length] - b[i];
                        Vector2 na = a[(i + 2) % a.Length] - a[(i + 1) % a.Length], nb = b[(i + 2) % b.Length] - b[(i + 1) % b.Length];
                        Assert.Equal(eb.Length(), ea.Length(), 2e-3f);
                        Assert.Equal(Angle(eb, nb), Angle(ea, na), 1e-4f);
                    }
                }

                foreach (var fin in new[] { FishPart.LeftCaudal, FishPart.RightCaudal })
                {
                    var finA = fish.GetLeaf(fin);
                    var finB = reference.GetLeaf(fin);
                    var tailA = fish.GetLeaf(FishPart.Tail3);
                    var tailB = reference.GetLeaf(FishPart.Tail3);
                    for (int i = 0; i < finA.Length; i++)
                    {
                        for (int j = 0; j < tailA.Length; j++)
                        {
                            Assert.Equal(Vector2.Distance(finB[i], tailB[j]), Vector2.Distance(finA[i], tailA[j]), 2e-3f);
                        }
                    }
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(13, trial, e);
            }
        }
    }

    [Fact]
    public void TailSegmentsChainAlongTheirJointDirections()
    {
        var rng = new Random(14);
        var fish = new FishModel(FishSize.Default, default);
        float[] lengths = [88f, 66f, 55f];
        for (int trial = 0; trial < 1000; trial++)
        {
            try
            {
                var pose = FishTestKit.Pose(rng);
                fish.SetPose(pose);
                Vector2 start = pose.Position - (80f * new Vector2(MathF.Cos(pose.Heading), MathF.Sin(pose.Heading)));
                float[] joints = [pose.Joint1, pose.Joint2, pose.Joint3];
                for (int i = 0; i < 3; i++)
                {
                    var leaf = fish.GetLeaf(FishPart.Tail1 + i);
                    Vector2 d = new(MathF.Cos(pose.Heading + joints[i]), MathF.Sin(pose.Heading + joints[i]));
                    Vector2 end = start - (lengths[i] * d);

                    // Two vertices lie on the line through the start across d, two on the line through the end.
                    int atStart = 0, atEnd = 0;
                    foreach (var v in leaf)
                    {
                        atStart += MathF.Abs(Vector2.Dot(v - start, d)) < 2e-3f ? 1 : 0;
                        atEnd += MathF.Abs(Vector2.Dot(v - end, d)) < 2e-3f ? 1 : 0;
                    }

                    Assert.Equal(2, atStart);
                    Assert.Equal(2, atEnd);
                    start = end;
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(14, trial, e);
            }
        }
    }

    [Fact]
    public void UnknownPartIsRejected()
    {
        var fish = new FishModel(FishSize.Default, default);
        var e = Assert.Throws<ArgumentException>(() => fish.GetLeaf((FishPart)8));
        Assert.Equal("part", e.ParamName);
        Assert.Contains("8", e.Message, StringComparison.Ordinal);
        Assert.Throws<ArgumentException>(() => fish.GetLeafBound((FishPart)(-1)));
    }

    [Fact]
    public void DefaultSizeIsRejected()
    {
        var e = Assert.Throws<ArgumentException>(() => new FishModel(default, default));
        Assert.Equal("size", e.ParamName);
    }

    /// <summary>The reference's definitions, written directly in world terms: P + a·u − b·n, Sᵢ ± hᵢ·nᵢ, Aₖ.</summary>
    internal static Vector2[][] ReferenceLeaves(FishSize s, FishPose pose)
    {
        Vector2 p = pose.Position;
        Vector2 u = new(MathF.Cos(pose.Heading), MathF.Sin(pose.Heading));
        Vector2 n = new(MathF.Sin(pose.Heading), -MathF.Cos(pose.Heading));
        Vector2 Body(float a, float b) => p + (a * u) - (b * n);
        float l = s.Length, w = s.Width;
        var leftFin = new[] { Body(-7f * l / 24f, (-w / 2f) - 37.5f), Body(-7f * l / 24f, (-w / 2f) - 25f), Body(-l / 12f, -w / 2f), Body(l / 4f, -w / 2f) };
        var body = new[] { Body(l / 2f, -w / 2f), Body((l / 2f) + s.Head, 0f), Body(l / 2f, w / 2f), Body(-l / 2f, w / 2f), Body(-l / 2f, -w / 2f) };
        var rightFin = new[] { Body(-7f * l / 24f, (w / 2f) + 37.5f), Body(-7f * l / 24f, (w / 2f) + 25f), Body(-l / 12f, w / 2f), Body(l / 4f, w / 2f) };
        float[] lengths = [s.Joint1, s.Joint2, s.Joint3];
        float[] joints = [pose.Joint1, pose.Joint2, pose.Joint3];
        float[] h = [0.266112f, 0.231336f, 0.115668f];
        float[] hEnd = [0.2193408f, 0.14994f, 0.089964f];
        var tails = new Vector2[3][];
        Vector2 start = Body(-l / 2f, 0f), d3 = default, n3 = default, e2 = default, e3 = default;
        for (int i = 0; i < 3; i++)
        {
            Vector2 d = new(MathF.Cos(pose.Heading + joints[i]), MathF.Sin(pose.Heading + joints[i]));
            Vector2 ni = new(d.Y, -d.X);
            Vector2 end = start - (lengths[i] * d);
            tails[i] = [start + (h[i] * lengths[i] * ni), start - (h[i] * lengths[i] * ni), end - (hEnd[i] * lengths[i] * ni), end + (hEnd[i] * lengths[i] * ni)];
            if (i == 1)
            {
                e2 = end;
            }

            (d3, n3, e3) = (d, ni, end);
            start = end;
        }

        Vector2 A(float k) => e2 - (k * s.Joint3 * d3);
        float h3 = hEnd[2] * s.Joint3;
        Vector2 notch = A(1.8f) + (10f * n3);
        var leftCaudal = new[] { A(2f) + (50f * n3), notch, e3 - (h3 * n3) };
        var rightCaudal = new[] { A(1.8f) - (35f * n3), notch, e3 + (h3 * n3) };
        return [leftFin, body, rightFin, tails[0], tails[1], tails[2], leftCaudal, rightCaudal];
    }

    /// <summary>Asserts that <paramref name="actual"/> is <paramref name="expected"/> up to a cyclic shift, in either direction.</summary>
    internal static void AssertSameCycle(Vector2[] expected, Vector2[] actual, float tolerance, string what)
    {
        Assert.Equal(expected.Length, actual.Length);
        int n = expected.Length;
        for (int shift = 0; shift < n; shift++)
        {
            foreach (int step in new[] { 1, -1 })
            {
                bool all = true;
                for (int i = 0; i < n && all; i++)
                {
                    Vector2 e = expected[(((shift + (step * i)) % n) + n) % n];
                    all = MathF.Abs(e.X - actual[i].X) <= tolerance && MathF.Abs(e.Y - actual[i].Y) <= tolerance;
                }

                if (all)
                {
                    return;
                }
            }
        }

        Assert.Fail($"{what}: vertices {string.Join(", ", actual)} are not the reference {string.Join(", ", expected)}");
    }

    private static float Angle(Vector2 a, Vector2 b) => MathF.Atan2((a.X * b.Y) - (a.Y * b.X), Vector2.Dot(a, b));
}
