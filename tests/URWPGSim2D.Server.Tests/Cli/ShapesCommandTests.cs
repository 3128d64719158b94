using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <c>shapes</c>: a fish's leaves against the reference's worked example and its formulas at
/// random poses and sizes, its tree circles enclosing their leaves, and the exact schema of
/// every shape kind.
/// </summary>
public sealed class ShapesCommandTests
{
    // The reference's worked example: deployed sizes, P = (0, 0), θ = 0, all φ = 0 (world x, z).
    private static readonly (double X, double Z)[][] WorkedExample =
    [
        [(-46.667, -60), (-46.667, -47.5), (-13.333, -22.5), (40, -22.5)],
        [(80, -22.5), (110, 0), (80, 22.5), (-80, 22.5), (-80, -22.5)],
        [(-46.667, 60), (-46.667, 47.5), (-13.333, 22.5), (40, 22.5)],
        [(-80, 23.418), (-80, -23.418), (-168, -19.302), (-168, 19.302)],
        [(-168, 15.268), (-168, -15.268), (-234, -9.896), (-234, 9.896)],
        [(-234, 6.362), (-234, -6.362), (-289, -4.948), (-289, 4.948)],
        [(-344, -50), (-333, -10), (-289, 4.948)],
        [(-333, 35), (-333, -10), (-289, -4.948)],
    ];

    [Fact]
    public void AFishAtHeadingZeroIsTheReferencesWorkedExample()
    {
        var fish = Single(Fish(0, 0, 0));

        Assert.Equal("fish", fish.GetProperty("type").GetString());
        var leaves = fish.GetProperty("leaves");
        for (int part = 0; part < 8; part++)
        {
            ReferenceFish.AssertSamePolygon(WorkedExample[part], Points(leaves.GetProperty(ReferenceFish.PartNames[part])), 1e-3, ReferenceFish.PartNames[part]);
        }
    }

    [Fact]
    public void TheFishSchemaHasTheLeavesInPartOrderThenTheThreeCircles()
    {
        var fish = Single(Fish(10, 20, 1, 0.1, 0.2, 0.3));

        Assert.Equal(["type", "leaves", "bounds"], Keys(fish));
        Assert.Equal(ReferenceFish.PartNames, Keys(fish.GetProperty("leaves")));
        Assert.Equal(["root", "body", "tail"], Keys(fish.GetProperty("bounds")));
        foreach (var circle in fish.GetProperty("bounds").EnumerateObject())
        {
            Assert.Equal(["center", "radius"], Keys(circle.Value));
        }

        int[] counts = [4, 5, 4, 4, 4, 4, 3, 3];
        for (int part = 0; part < 8; part++)
        {
            Assert.Equal(counts[part], fish.GetProperty("leaves").GetProperty(ReferenceFish.PartNames[part]).GetArrayLength());
        }
    }

    [Fact]
    public void LeavesFollowTheReferenceFormulasAtRandomPosesAndSizes()
    {
        var random = new Random(20240603);
        var inputs = new List<(double[] Size, double[] Pose)>();
        for (int i = 0; i < 200; i++)
        {
            double[] size = i % 2 == 0 ? ReferenceFish.DeployedSize :
                [F(random, 100, 250), F(random, 30, 70), F(random, 15, 50), F(random, 50, 120), F(random, 40, 90), F(random, 30, 80)];
            double[] pose = [F(random, -1400, 1400), F(random, -900, 900), F(random, -4, 4), F(random, -0.9, 0.9), F(random, -0.9, 0.9), F(random, -0.9, 0.9)];
            inputs.Add((size, pose));
        }

        var output = Run(Shapes([.. inputs.Select(p => Fish(p.Pose[0], p.Pose[1], p.Pose[2], p.Pose[3], p.Pose[4], p.Pose[5], p.Size))]));

        for (int i = 0; i < inputs.Count; i++)
        {
            var (size, pose) = inputs[i];
            var expected = ReferenceFish.Leaves(size, (float)pose[0], (float)pose[1], (float)pose[2], (float)pose[3], (float)pose[4], (float)pose[5]);
            var leaves = output[i].GetProperty("leaves");
            for (int part = 0; part < 8; part++)
            {
                ReferenceFish.AssertSamePolygon(expected[part], Points(leaves.GetProperty(ReferenceFish.PartNames[part])), 2e-3, $"shapes[{i}].{ReferenceFish.PartNames[part]}");
            }
        }
    }

    [Fact]
    public void EachTreeCircleIsTheMinimumEnclosingCircleOfItsLeaves()
    {
        // Independent truth: the reference's leaf polygons (ReferenceFish) and a brute-force
        // minimum enclosing circle over their vertices (every circle through two or three of them,
        // the smallest that holds all). The output's circle must hold every vertex; the body group's
        // is the minimum circle, the tail group's and the root's at most 1/cos 22.5° ≈ 1.0824 times
        // it (docs/fish.md, "Enclosure and tightness"), each grown by a few µm against round-off.
        var random = new Random(7);
        var poses = Enumerable.Range(0, 30).Select(_ => new[] { F(random, -500, 500), F(random, -500, 500), F(random, -4, 4), F(random, -1, 1), F(random, -1, 1), F(random, -1, 1) }).ToArray();

        var output = Run(Shapes([.. poses.Select(p => Fish(p[0], p[1], p[2], p[3], p[4], p[5]))]));

        for (int i = 0; i < poses.Length; i++)
        {
            var p = poses[i];
            var reference = ReferenceFish.Leaves(ReferenceFish.DeployedSize, (float)p[0], (float)p[1], (float)p[2], (float)p[3], (float)p[4], (float)p[5]);
            var bounds = output[i].GetProperty("bounds");
            (string Name, int First, int End, double Factor)[] circles = [("root", 0, 8, 1.0824), ("body", 0, 3, 1.0), ("tail", 3, 8, 1.0824)];
            foreach (var (name, first, end, factor) in circles)
            {
                var vertices = reference[first..end].SelectMany(leaf => leaf).ToList();
                double smallest = MinimumEnclosingRadius(vertices);
                var (center, radius) = CircleOf(bounds.GetProperty(name));
                string where = $"shapes[{i}] (seed 7, pose {string.Join(", ", p)}) {name} circle";
                foreach (var v in vertices)
                {
                    double distance = Math.Sqrt(((v.X - center.X) * (v.X - center.X)) + ((v.Z - center.Z) * (v.Z - center.Z)));
                    Assert.True(distance <= radius + 2e-3, $"{where}: vertex {v} is outside ({distance} > {radius})");
                }

                Assert.True(radius <= (factor * smallest) + 5e-3, $"{where}: radius {radius} is more than {factor} times the minimum {smallest}");
            }
        }
    }

    // The radius of the smallest circle holding every point: brute force over the circles whose
    // boundary passes through two points (as a diameter) or three (circumcircle).
    private static double MinimumEnclosingRadius(List<(double X, double Z)> points)
    {
        double best = double.PositiveInfinity;
        bool Holds(double cx, double cz, double r) =>
            points.All(q => Math.Sqrt(((q.X - cx) * (q.X - cx)) + ((q.Z - cz) * (q.Z - cz))) <= r + 1e-7);
        for (int a = 0; a < points.Count; a++)
        {
            for (int b = a + 1; b < points.Count; b++)
            {
                double cx = (points[a].X + points[b].X) / 2, cz = (points[a].Z + points[b].Z) / 2;
                double r = Math.Sqrt(((points[a].X - cx) * (points[a].X - cx)) + ((points[a].Z - cz) * (points[a].Z - cz)));
                if (r < best && Holds(cx, cz, r))
                {
                    best = r;
                }

                for (int c = b + 1; c < points.Count; c++)
                {
                    var (ax, az) = points[a];
                    var (bx, bz) = points[b];
                    var (qx, qz) = points[c];
                    double d = 2 * ((ax * (bz - qz)) + (bx * (qz - az)) + (qx * (az - bz)));
                    if (Math.Abs(d) < 1e-12)
                    {
                        continue;
                    }

                    double ux = ((((ax * ax) + (az * az)) * (bz - qz)) + (((bx * bx) + (bz * bz)) * (qz - az)) + (((qx * qx) + (qz * qz)) * (az - bz))) / d;
                    double uz = ((((ax * ax) + (az * az)) * (qx - bx)) + (((bx * bx) + (bz * bz)) * (ax - qx)) + (((qx * qx) + (qz * qz)) * (bx - ax))) / d;
                    double rr = Math.Sqrt(((ax - ux) * (ax - ux)) + ((az - uz) * (az - uz)));
                    if (rr < best && Holds(ux, uz, rr))
                    {
                        best = rr;
                    }
                }
            }
        }

        return best;
    }

    [Fact]
    public void ACircleIsItsCentreAndRadiusWithItselfAsOuterCircle()
    {
        Assert.Equal(
            """{"type":"circle","center":[1,-2],"radius":3,"outer":{"center":[1,-2],"radius":3}}""",
            SingleText(Circle(1, -2, 3)));
    }

    [Fact]
    public void ABoxIsItsCornersCounterClockwiseFromMinWithItsHalfDiagonalAsOuterRadius()
    {
        Assert.Equal(
            """{"type":"aabb","min":[0,0],"max":[6,8],"vertices":[[0,0],[6,0],[6,8],[0,8]],"outer":{"center":[3,4],"radius":5}}""",
            SingleText(Aabb(0, 0, 6, 8)));
    }

    [Fact]
    public void APolygonGivenClockwiseIsWrittenCounterClockwise()
    {
        // (0,0) → (0,10) → (10,0) turns clockwise in (x, z); the library stores it reversed.
        var polygon = Single(Polygon((0, 0), (0, 10), (10, 0)));

        Assert.Equal(["type", "vertices", "outer"], Keys(polygon));
        Assert.Equal([(10.0, 0.0), (0.0, 10.0), (0.0, 0.0)], Points(polygon.GetProperty("vertices")));
        var (center, radius) = CircleOf(polygon.GetProperty("outer"));
        Assert.Equal(10.0 / 3, center.X, 5);
        Assert.Equal(10.0 / 3, center.Z, 5);
        Assert.Equal(Math.Sqrt((20.0 / 3 * 20.0 / 3) + (10.0 / 3 * 10.0 / 3)), radius, 5);
    }

    [Fact]
    public void ASegmentIsItsEndsAsTwoVerticesWithTheCircleOnItsMiddle()
    {
        Assert.Equal(
            """{"type":"segment","a":[0,0],"b":[3,4],"vertices":[[0,0],[3,4]],"outer":{"center":[1.5,2],"radius":2.5}}""",
            SingleText(Segment(0, 0, 3, 4)));
    }

    [Fact]
    public void AnEightDopIsItsTightenedSlabsAndItsPolygon()
    {
        // The box |x|, |z| ≤ 10 with loose diagonal slabs ±100: they tighten to ±10√2 (through
        // the corners) and the polygon is the square.
        var kdop = Single(KDop8([-10, -10, -100, -100], [10, 10, 100, 100]));

        Assert.Equal(["type", "min", "max", "vertices", "outer"], Keys(kdop));
        double d = 10 * Math.Sqrt(2);
        double[] min = [.. kdop.GetProperty("min").EnumerateArray().Select(e => e.GetDouble())];
        double[] max = [.. kdop.GetProperty("max").EnumerateArray().Select(e => e.GetDouble())];
        Assert.Equal([-10, -10, -d, -d], min, new Near(1e-4));
        Assert.Equal([10, 10, d, d], max, new Near(1e-4));
        var square = Points(kdop.GetProperty("vertices")).Distinct().ToList();
        ReferenceFish.AssertSamePolygon([(-10, -10), (10, -10), (10, 10), (-10, 10)], square, 1e-4, "8-DOP");
        var (center, radius) = CircleOf(kdop.GetProperty("outer"));
        Assert.Equal(0, center.X, 4);
        Assert.Equal(0, center.Z, 4);
        Assert.Equal(d, radius, 4);
    }

    [Fact]
    public void AllKindsInOneArrayKeepTheirOrderAndEachStartsWithItsType()
    {
        var output = Run(Shapes(Segment(0, 0, 1, 1), Fish(0, 0, 0), Circle(0, 0, 1), Polygon((0, 0), (1, 0), (0, 1)), Aabb(0, 0, 1, 1), Diamond(0, 0, 1)));

        Assert.Equal(["segment", "fish", "circle", "polygon", "aabb", "kdop8"], output.Select(e => Keys(e)[0] == "type" ? e.GetProperty("type").GetString() : null));
    }

    [Fact]
    public void AnEmptyArrayGivesAnEmptyArray()
    {
        var run = CliRun.Shapes("[]");

        Assert.Equal((0, "[]\n", string.Empty), (run.ExitCode, run.Stdout, run.Stderr));
    }

    [Fact]
    public void AFileGivesTheSameAsStandardInput()
    {
        string json = Shapes(Fish(5, 6, 0.5, 0.1, 0.2, 0.3), Circle(1, 2, 3));
        string file = Path.Combine(Path.GetTempPath(), $"urwpgsim2d-shapes-{Guid.NewGuid():N}.json");
        File.WriteAllText(file, json);
        try
        {
            var fromFile = CliRun.Of(string.Empty, "shapes", file);
            var fromStdin = CliRun.Shapes(json);

            Assert.Equal((0, string.Empty), (fromFile.ExitCode, fromFile.Stderr));
            Assert.Equal(fromStdin.Stdout, fromFile.Stdout);
            Assert.EndsWith("]\n", fromFile.Stdout, StringComparison.Ordinal);
            Assert.Single(fromFile.Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries));
        }
        finally
        {
            File.Delete(file);
        }
    }

    internal static List<(double X, double Z)> Points(JsonElement array) =>
        [.. array.EnumerateArray().Select(p => (p[0].GetDouble(), p[1].GetDouble()))];

    internal static string[] Keys(JsonElement obj) => [.. obj.EnumerateObject().Select(p => p.Name)];

    private static ((double X, double Z) Center, double Radius) CircleOf(JsonElement circle) =>
        ((circle.GetProperty("center")[0].GetDouble(), circle.GetProperty("center")[1].GetDouble()), circle.GetProperty("radius").GetDouble());

    private static double F(Random random, double lo, double hi) => (float)(lo + ((hi - lo) * random.NextDouble()));

    private static List<JsonElement> Run(string json)
    {
        var run = CliRun.Shapes(json);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Equal(string.Empty, run.Stderr);
        return [.. JsonDocument.Parse(run.Stdout).RootElement.EnumerateArray()];
    }

    private static JsonElement Single(string shape) => Assert.Single(Run(Shapes(shape)));

    private static string SingleText(string shape)
    {
        var run = CliRun.Shapes(Shapes(shape));
        Assert.Equal((0, string.Empty), (run.ExitCode, run.Stderr));
        Assert.StartsWith("[", run.Stdout, StringComparison.Ordinal);
        Assert.EndsWith("]\n", run.Stdout, StringComparison.Ordinal);
        return run.Stdout[1..^2];
    }

    private sealed class Near(double tolerance) : IEqualityComparer<double>
    {
        public bool Equals(double x, double y) => Math.Abs(x - y) <= tolerance;

        public int GetHashCode(double obj) => 0;
    }
}
