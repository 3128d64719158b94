namespace URWPGSim2D.Collision.Tests.Fish;

public class FishBoundingVolumeTests
{
    private static readonly FishPart[] BodyParts = [FishPart.LeftPectoral, FishPart.Body, FishPart.RightPectoral];
    private static readonly FishPart[] TailParts = [FishPart.Tail1, FishPart.Tail2, FishPart.Tail3, FishPart.LeftCaudal, FishPart.RightCaudal];

    [Fact]
    public void EveryCircleEnclosesEverythingBelowIt()
    {
        var rng = new Random(21);
        var fish = new FishModel(FishSize.Default, default);
        for (int trial = 0; trial < 5000; trial++)
        {
            if (trial % 500 == 0)
            {
                fish = new FishModel(trial == 0 ? FishSize.Default : FishTestKit.Size(rng), default);
            }

            fish.SetPose(FishTestKit.Pose(rng, spread: 1500f));
            AssertEncloses(fish.BodyGroup, fish, BodyParts, trial);
            AssertEncloses(fish.TailGroup, fish, TailParts, trial);
            AssertEncloses(fish.Root, fish, FishTestKit.AllParts, trial);
        }
    }

    [Fact]
    public void CirclesEncloseTheirLeavesAtHugeHeadingsAndFarAway()
    {
        // The tail group and root circles are computed in the body frame and moved rigidly; the
        // leaves are placed through each frame's own angle θ + φᵢ. Large |θ| makes that sum round
        // coarsely, far positions make every coordinate round coarsely: the circles must still hold.
        var rng = new Random(28);
        var fish = new FishModel(FishSize.Default, default);
        float[] headings = [1000f, -1000f, 123456f, 6.2831855f, -3.1415927f];
        for (int trial = 0; trial < 5000; trial++)
        {
            if (trial % 500 == 499)
            {
                fish = new FishModel(FishTestKit.Size(rng), default);
            }

            var random = FishTestKit.Pose(rng, MathF.PI, trial % 2 == 0 ? 25000f : 1500f);
            float heading = trial % 3 == 0 ? headings[rng.Next(headings.Length)] + random.Heading : random.Heading;
            fish.SetPose(new FishPose(random.Position, heading, random.Joint1, random.Joint2, random.Joint3));
            AssertEncloses(fish.BodyGroup, fish, BodyParts, trial);
            AssertEncloses(fish.TailGroup, fish, TailParts, trial);
            AssertEncloses(fish.Root, fish, FishTestKit.AllParts, trial);
        }
    }

    [Fact]
    public void CirclesDependOnThePoseOnlyNotOnThePosesBefore()
    {
        // The tail and root circles are kept between poses with the same joint angles: a model that
        // went through other poses first must end up bit for bit like a fresh one.
        var rng = new Random(29);
        var travelled = new FishModel(FishSize.Default, default);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                var pose = FishTestKit.Pose(rng, 1f, 1500f);
                var sameJoints = new FishPose(FishTestKit.Point(rng, 1500f), FishTestKit.Range(rng, -3f, 3f), pose.Joint1, pose.Joint2, pose.Joint3);
                travelled.SetPose(trial % 2 == 0 ? sameJoints : FishTestKit.Pose(rng, 1f, 1500f));
                travelled.SetPose(pose);
                var fresh = new FishModel(FishSize.Default, pose);
                Assert.Equal(fresh.Root.Center, travelled.Root.Center);
                Assert.Equal(fresh.Root.Radius, travelled.Root.Radius);
                Assert.Equal(fresh.TailGroup.Center, travelled.TailGroup.Center);
                Assert.Equal(fresh.TailGroup.Radius, travelled.TailGroup.Radius);
                Assert.Equal(fresh.BodyGroup.Center, travelled.BodyGroup.Center);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(29, trial, e);
            }
        }
    }

    [Fact]
    public void CirclesAreWithinThirtyPercentOfTheSmallestEnclosingCircle()
    {
        // Against the exhaustive smallest circle (slow: a few hundred poses).
        var rng = new Random(22);
        var fish = new FishModel(FishSize.Default, default);
        var worst = new Ratios();
        for (int trial = 0; trial < 300; trial++)
        {
            if (trial % 100 == 99)
            {
                fish = new FishModel(FishTestKit.Size(rng), default);
            }

            // Half the poses swim (joints within ±0.6 rad), half bend anyhow (±π, even folded back).
            fish.SetPose(FishTestKit.Pose(rng, trial % 2 == 0 ? 0.6f : MathF.PI, 1500f));
            worst.Add(fish, ExhaustiveMinimumRadius);
        }

        worst.AssertWithinBounds();
    }

    [Fact]
    public void CirclesStayTightOverThousandsOfPosesIncludingExtremeJoints()
    {
        // Against the library's exact incremental search (itself checked against exhaustion below):
        // random sizes, joints anywhere, at ±90° and ±180° exactly, and far from the origin.
        var rng = new Random(25);
        float[] extremes = [MathF.PI / 2f, -MathF.PI / 2f, MathF.PI, -MathF.PI, 0f];
        var fish = new FishModel(FishSize.Default, default);
        var worst = new Ratios();
        for (int trial = 0; trial < 6000; trial++)
        {
            if (trial % 500 == 499)
            {
                fish = new FishModel(FishTestKit.Size(rng), default);
            }

            var pose = FishTestKit.Pose(rng, trial % 3 == 0 ? 0.6f : MathF.PI, trial % 7 == 0 ? 20000f : 1500f);
            if (trial % 4 == 1)
            {
                pose = new FishPose(pose.Position, pose.Heading, Pick(rng, extremes), Pick(rng, extremes), Pick(rng, extremes));
            }

            fish.SetPose(pose);
            worst.Add(fish, points => EnclosingCircle.Minimum(points).Radius);
        }

        worst.AssertWithinBounds();
    }

    [Fact]
    public void EnclosingCircleSearchIsExactOnAwkwardPointSets()
    {
        var rng = new Random(24);
        for (int trial = 0; trial < 3000; trial++)
        {
            int n = rng.Next(1, 20);
            var points = new Vector2[n];
            for (int i = 0; i < n; i++)
            {
                points[i] = (trial % 4) switch
                {
                    0 => FishTestKit.Point(rng, 300f) + new Vector2(1000f, -700f),
                    1 => new Vector2(FishTestKit.Range(rng, -200f, 200f), 5f) * new Vector2(1f, (float)rng.Next(0, 2)), // collinear or two rows
                    2 => i > 0 && rng.Next(3) == 0 ? points[rng.Next(i)] : FishTestKit.Point(rng, 50f), // repeats
                    _ => 100f * new Vector2(MathF.Cos(i * 2f * MathF.PI / n), MathF.Sin(i * 2f * MathF.PI / n)), // co-circular
                };
            }

            var circle = EnclosingCircle.Minimum(points);
            foreach (var p in points)
            {
                Assert.True(Dist(p, circle.Center.X, circle.Center.Y) <= circle.Radius, $"trial {trial}: a point is outside");
            }

            double exact = n == 1 ? 0 : ExhaustiveMinimumRadius(points);
            Assert.True(circle.Radius <= (exact * (1 + 1e-4)) + 1e-2, $"trial {trial}: radius {circle.Radius} vs minimum {exact}");
        }
    }

    [Fact]
    public void FarthestSquaredEqualsThePointByPointMaximum()
    {
        var rng = new Random(27);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                var points = new Vector2[trial % 33];
                for (int i = 0; i < points.Length; i++)
                {
                    points[i] = FishTestKit.Point(rng, 2000f);
                }

                Vector2 c = FishTestKit.Point(rng, 2000f);
                float expected = 0f;
                foreach (var p in points)
                {
                    expected = MathF.Max(expected, Vector2.DistanceSquared(p, c));
                }

                Assert.Equal(expected, EnclosingCircle.FarthestSquared(points, c));
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(27, trial, e);
            }
        }
    }

    [Fact]
    public void OriginalRadiiWouldMissTheCaudalTipsButOursDoNot()
    {
        // The reference notes the original's root radius (L + L1 + L2 + L3)/2 = 184 does not reach
        // the caudal tips (~274 mm from its centre). Ours reaches every vertex (checked above) and is no
        // smaller than half the fish's straight extent: head tip 110 to left caudal tip −344.
        var fish = new FishModel(FishSize.Default, default);
        Assert.True(fish.Root.Radius >= 227f);
        Assert.True(fish.Root.Radius <= 227f * 1.3f);
    }

    [Fact]
    public void LeafBoundsAndBoundsAreTheExtremeCoordinates()
    {
        var rng = new Random(23);
        var fish = new FishModel(FishSize.Default, default);
        for (int trial = 0; trial < 1000; trial++)
        {
            try
            {
                fish.SetPose(FishTestKit.Pose(rng, spread: 1500f));
                Vector2 lo = new(float.MaxValue), hi = new(float.MinValue);
                foreach (var part in FishTestKit.AllParts)
                {
                    var leaf = fish.GetLeaf(part);
                    var bound = fish.GetLeafBound(part);
                    for (int axis = 0; axis < 4; axis++)
                    {
                        float min = float.MaxValue, max = float.MinValue;
                        foreach (var v in leaf)
                        {
                            float p = Vector2.Dot(v, KDop8.Axis(axis));
                            min = MathF.Min(min, p);
                            max = MathF.Max(max, p);
                        }

                        Assert.Equal(min, bound.GetMin(axis), 2e-3f);
                        Assert.Equal(max, bound.GetMax(axis), 2e-3f);
                    }

                    foreach (var v in leaf)
                    {
                        lo = Vector2.Min(lo, v);
                        hi = Vector2.Max(hi, v);
                    }
                }

                Assert.Equal(lo, fish.Bounds.Min);
                Assert.Equal(hi, fish.Bounds.Max);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(23, trial, e);
            }
        }
    }

    /// <summary>The smallest enclosing circle by exhaustion: the smallest of all circles on two or three of the points that holds them all.</summary>
    internal static double ExhaustiveMinimumRadius(Vector2[] points)
    {
        double best = double.PositiveInfinity;
        int n = points.Length;
        for (int i = 0; i < n; i++)
        {
            for (int j = i + 1; j < n; j++)
            {
                double cx = 0.5 * (points[i].X + points[j].X), cz = 0.5 * (points[i].Y + points[j].Y);
                Consider(points, cx, cz, Dist(points[i], cx, cz), ref best);
                for (int k = j + 1; k < n; k++)
                {
                    if (Circumcircle(points[i], points[j], points[k], out cx, out cz))
                    {
                        Consider(points, cx, cz, Dist(points[i], cx, cz), ref best);
                    }
                }
            }
        }

        return best;
    }

    private static void Consider(Vector2[] points, double cx, double cz, double r, ref double best)
    {
        if (r >= best)
        {
            return;
        }

        foreach (var p in points)
        {
            if (Dist(p, cx, cz) > r * (1 + 1e-9) + 1e-9)
            {
                return;
            }
        }

        best = r;
    }

    private static bool Circumcircle(Vector2 a, Vector2 b, Vector2 c, out double cx, out double cz)
    {
        double bx = b.X - a.X, bz = b.Y - a.Y, qx = c.X - a.X, qz = c.Y - a.Y;
        double d = 2 * ((bx * qz) - (bz * qx));
        cx = cz = 0;
        if (Math.Abs(d) < 1e-12)
        {
            return false;
        }

        double b2 = (bx * bx) + (bz * bz), q2 = (qx * qx) + (qz * qz);
        cx = a.X + (((qz * b2) - (bz * q2)) / d);
        cz = a.Y + (((bx * q2) - (qx * b2)) / d);
        return true;
    }

    private static double Dist(Vector2 p, double cx, double cz) => Math.Sqrt(((p.X - cx) * (p.X - cx)) + ((p.Y - cz) * (p.Y - cz)));

    private static Vector2[] Points(FishModel fish, FishPart[] parts)
    {
        var list = new System.Collections.Generic.List<Vector2>();
        foreach (var part in parts)
        {
            list.AddRange(fish.GetLeaf(part).ToArray());
        }

        return [.. list];
    }

    private static float Pick(Random rng, float[] values) => values[rng.Next(values.Length)];

    /// <summary>The worst ratio of each circle to the smallest circle around its leaves' vertices.</summary>
    private sealed class Ratios
    {
        // Tail group and root circles are centred on the smallest fixed-axis octagon: at most
        // 1/cos 22.5° = 1.08239 times the minimum (plus µm slack); the issue asks for 1.30.
        private const double OctagonBound = 1.0825;

        private double _body, _tail, _root;

        public void Add(FishModel fish, Func<Vector2[], double> minimumRadius)
        {
            _body = Math.Max(_body, fish.BodyGroup.Radius / minimumRadius(Points(fish, BodyParts)));
            _tail = Math.Max(_tail, fish.TailGroup.Radius / minimumRadius(Points(fish, TailParts)));
            _root = Math.Max(_root, fish.Root.Radius / minimumRadius(Points(fish, FishTestKit.AllParts)));
        }

        public void AssertWithinBounds()
        {
            Assert.True(_body <= 1.0001, $"body group circle ratio {_body}: it is the minimum circle, moved rigidly");
            Assert.True(_tail <= OctagonBound, $"tail group circle ratio {_tail}");
            Assert.True(_root <= OctagonBound, $"root circle ratio {_root}");
            Assert.True(_root > 1.0, $"root ratio {_root}: the measurement is suspicious (the root is not a minimum circle)");
        }
    }

    private static void AssertEncloses(Circle circle, FishModel fish, FishPart[] parts, int trial)
    {
        foreach (var p in Points(fish, parts))
        {
            double d = Dist(p, circle.Center.X, circle.Center.Y);
            Assert.True(d <= circle.Radius, $"trial {trial}: vertex ({p.X}, {p.Y}) is {d - circle.Radius} mm outside the circle of {string.Join("+", parts)}");
        }
    }
}
