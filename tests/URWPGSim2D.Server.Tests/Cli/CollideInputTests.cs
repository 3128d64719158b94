using URWPGSim2D.Collision;
using Xunit.Sdk;
using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>Where the input comes from, output order and number formatting of <c>collide</c>.</summary>
public sealed class CollideInputTests
{
    [Fact]
    public void ManyRandomCirclePairsComeBackInOrderAndMatchTheAnalyticAnswer()
    {
        var random = new Random(20240602);
        const int count = 400;
        var circles = new (double X, double Z, double R)[count, 2];
        var pairs = new string[count];
        for (int i = 0; i < count; i++)
        {
            for (int k = 0; k < 2; k++)
            {
                // Integers keep the input exact in single precision.
                circles[i, k] = (random.Next(-50, 51), random.Next(-50, 51), random.Next(1, 40));
            }

            pairs[i] = Pair(Circle(circles[i, 0].X, circles[i, 0].Z, circles[i, 0].R), Circle(circles[i, 1].X, circles[i, 1].Z, circles[i, 1].R));
        }

        var run = CliRun.Collide(Pairs(pairs));

        Assert.Equal(0, run.ExitCode);
        using var doc = JsonDocument.Parse(run.Stdout);
        Assert.Equal(count, doc.RootElement.GetArrayLength());
        int intersecting = 0;
        for (int i = 0; i < count; i++)
        {
            try
            {
                var (a, b) = (circles[i, 0], circles[i, 1]);
                double dx = a.X - b.X, dz = a.Z - b.Z, d = Math.Sqrt((dx * dx) + (dz * dz));
                var result = doc.RootElement[i];
                bool overlap = d < a.R + b.R;
                Assert.Equal(overlap, result.GetProperty("intersect").GetBoolean());
                if (!overlap || d == 0)
                {
                    continue;
                }

                intersecting++;
                double depth = a.R + b.R - d, nx = dx / d, nz = dz / d;

                // The action point is the middle of [max(−r_b, d − r_a), min(r_b, d + r_a)] on the line from b's centre along the normal.
                double t = 0.5 * (Math.Max(-b.R, d - a.R) + Math.Min(b.R, d + a.R));
                AssertClose(result, "mtv", nx * depth, nz * depth, i);
                AssertClose(result, "normal", nx, nz, i);
                AssertClose(result, "actionPoint", b.X + (t * nx), b.Z + (t * nz), i);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(20240602, i, e);
            }
        }

        Assert.InRange(intersecting, count / 10, count - 1);
    }

    [Fact]
    public void NumbersAreTheLibrarysSinglePrecisionValuesInShortestRoundTripForm()
    {
        // Irrational contacts: every output number must parse back to exactly the library's float
        // and be written the way float.ToString() writes its shortest round-trip form.
        var random = new Random(7);
        const int count = 200;
        var shapes = new (Shape A, Shape B)[count];
        var pairs = new string[count];
        for (int i = 0; i < count; i++)
        {
            float ax = random.NextSingle() * 10, az = random.NextSingle() * 10, bx = random.NextSingle() * 10, bz = random.NextSingle() * 10;
            float h = 1 + (random.NextSingle() * 5), r = 1 + (random.NextSingle() * 5);
            shapes[i] = (new Circle(new Vector2(ax, az), r), new Aabb(new Vector2(bx - h, bz - h), new Vector2(bx + h, bz + h)));
            pairs[i] = Pair(
                $$"""{"type":"circle","center":[{{F(ax)}},{{F(az)}}],"radius":{{F(r)}}}""",
                $$"""{"type":"aabb","min":[{{F(bx - h)}},{{F(bz - h)}}],"max":[{{F(bx + h)}},{{F(bz + h)}}]}""");
        }

        var run = CliRun.Collide(Pairs(pairs));

        Assert.Equal(0, run.ExitCode);
        using var doc = JsonDocument.Parse(run.Stdout);
        for (int i = 0; i < count; i++)
        {
            try
            {
                var expected = CollisionDetector.Detect(shapes[i].A, shapes[i].B);
                var result = doc.RootElement[i];
                Assert.Equal(expected.Intersect, result.GetProperty("intersect").GetBoolean());
                AssertExact(result.GetProperty("mtv"), expected.MinimumTranslationVector);
                AssertExact(result.GetProperty("normal"), expected.NormalAxis);
                AssertExact(result.GetProperty("actionPoint"), expected.ActionPoint);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(7, i, e);
            }
        }
    }

    [Fact]
    public void StdinAndFileGiveTheSameOutput()
    {
        string json = Pairs(Pair(Circle(0, 0, 10), Circle(16, 0, 10)), Pair(Segment(0, 0, 10, 0), Segment(2, -1, 2, 9)));
        string file = Path.Combine(Path.GetTempPath(), $"urwpgsim2d-collide-{Guid.NewGuid():N}.json");
        File.WriteAllText(file, json, new UTF8Encoding(encoderShouldEmitUTF8Identifier: true));
        try
        {
            var fromStdin = CliRun.Of(json, "collide", "-");
            var fromFile = CliRun.Of("this stdin must not be read", "collide", file);

            Assert.Equal((0, 0), (fromStdin.ExitCode, fromFile.ExitCode));
            Assert.Equal(
                "[{\"intersect\":true,\"mtv\":[-4,0],\"normal\":[-1,0],\"actionPoint\":[8,0]}," +
                "{\"intersect\":true,\"mtv\":[0,-1],\"normal\":[0,-1],\"actionPoint\":[2,0]}]\n",
                fromStdin.Stdout);
            Assert.Equal(fromStdin.Stdout, fromFile.Stdout);
            Assert.Equal(string.Empty, fromFile.Stderr);
        }
        finally
        {
            File.Delete(file);
        }
    }

    [Fact]
    public void AnEmptyArrayGivesAnEmptyArray()
    {
        var run = CliRun.Collide(" [ ] ");

        Assert.Equal((0, "[]\n", string.Empty), (run.ExitCode, run.Stdout, run.Stderr));
    }

    [Fact]
    public void UnknownFieldsAndWhitespaceAreIgnored()
    {
        string json = """
            [
              {
                "comment": "fields a SHAPE type does not use are ignored",
                "a": { "type": "circle", "center": [0, 0], "radius": 10, "vertices": [[1, 2]], "color": "red" },
                "b": { "radius": 10, "center": [16, 0], "type": "circle" }
              }
            ]
            """;

        var run = CliRun.Collide(json);

        Assert.Equal("[{\"intersect\":true,\"mtv\":[-4,0],\"normal\":[-1,0],\"actionPoint\":[8,0]}]\n", run.Stdout);
    }

    [Fact]
    public void NegativeZeroIsWrittenAsZero()
    {
        // Circle above a box face: the normal (0, −1) comes out of the library with x = −0 or 0;
        // either way the output must say 0.
        var run = CliRun.Collide(Pairs(Pair(Aabb(-5, 7, 5, 20), Circle(0, 0, 10)), Pair(Circle(0, 0, 10), Aabb(-5, 7, 5, 20))));

        Assert.Equal(
            "[{\"intersect\":true,\"mtv\":[0,3],\"normal\":[0,1],\"actionPoint\":[0,8.5]}," +
            "{\"intersect\":true,\"mtv\":[0,-3],\"normal\":[0,-1],\"actionPoint\":[0,8.5]}]\n",
            run.Stdout);
    }

    private static string F(float value) => value.ToString("R", CultureInfo.InvariantCulture);

    private static void AssertClose(JsonElement result, string name, double x, double z, int index)
    {
        var v = result.GetProperty(name);
        Assert.True(Math.Abs(v[0].GetDouble() - x) < 1e-4 && Math.Abs(v[1].GetDouble() - z) < 1e-4, $"pair {index} {name}: [{v[0]}, {v[1]}], expected [{x}, {z}]");
    }

    private static void AssertExact(JsonElement pair, Vector3 expected)
    {
        float x = expected.X == 0 ? 0 : expected.X, z = expected.Z == 0 ? 0 : expected.Z;
        Assert.Equal(x.ToString(CultureInfo.InvariantCulture), pair[0].GetRawText());
        Assert.Equal(z.ToString(CultureInfo.InvariantCulture), pair[1].GetRawText());
        Assert.Equal(x, pair[0].GetSingle());
        Assert.Equal(z, pair[1].GetSingle());
    }
}
