using URWPGSim2D.Collision;
using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// Adding the fish to <c>collide</c> changes nothing for pairs without a fish: the documented
/// example gives its documented bytes, and random pairs of the five primitive kinds give exactly
/// the documented format (written by the test itself from the library's results), with no part
/// fields.
/// </summary>
public sealed class CollideCompatibilityTests
{
    [Fact]
    public void TheDocumentedExampleGivesTheDocumentedBytes()
    {
        // docs/cli.md, "Example" (also examples/pairs.json and pairs.expected.json).
        string pairs = Pairs(
            Pair(Circle(0, 0, 3), Circle(3, 4, 3)),
            Pair(Aabb(0, 0, 10, 10), Polygon((8, 5), (20, -1), (20, 11))),
            Pair(KDop8([-10, -10, -7.0710678, -7.0710678], [10, 10, 7.0710678, 7.0710678]), Segment(8, -20, 8, 20)),
            Pair(Circle(0, 0, 10), Circle(20, 0, 10)));

        var run = CliRun.Collide(pairs);

        Assert.Equal((0, string.Empty), (run.ExitCode, run.Stderr));
        Assert.Equal(
            "[{\"intersect\":true,\"mtv\":[-0.6,-0.8],\"normal\":[-0.6,-0.8],\"actionPoint\":[1.5,2]},"
            + "{\"intersect\":true,\"mtv\":[-2,0],\"normal\":[-1,0],\"actionPoint\":[9,5]},"
            + "{\"intersect\":true,\"mtv\":[-2,0],\"normal\":[-1,0],\"actionPoint\":[8,0]},"
            + "{\"intersect\":false,\"mtv\":[0,0],\"normal\":[0,0],\"actionPoint\":[0,0]}]\n",
            run.Stdout);
    }

    [Fact]
    public void RandomPrimitivePairsGiveExactlyThePreFishOutput()
    {
        var random = new Random(4242);
        var texts = new List<string>();
        var shapes = new List<(Shape A, Shape B)>();
        for (int i = 0; i < 800; i++)
        {
            var (aText, a) = RandomShape(random);
            var (bText, b) = RandomShape(random);
            texts.Add(Pair(aText, bText));
            shapes.Add((a, b));
        }

        var run = CliRun.Collide(Pairs([.. texts]));

        // The expected bytes are written here by hand from docs/cli.md's format (not by the
        // command's own DTO and serializer): one object per pair, keys in this order, [x, z] pairs,
        // numbers in their shortest round-trip form, −0 written as 0, no part fields.
        var results = shapes.Select(p => CollisionDetector.Detect(p.A, p.B)).ToArray();
        string expected = "[" + string.Join(",", results.Select(Documented)) + "]\n";
        Assert.Equal((0, string.Empty), (run.ExitCode, run.Stderr));
        Assert.Equal(expected, run.Stdout);
        Assert.DoesNotContain("part", run.Stdout, StringComparison.Ordinal);
        Assert.InRange(results.Count(r => r.Intersect), 100, 700);
    }

    private static string Documented(CollisionDetectionResult r) =>
        $"{{\"intersect\":{(r.Intersect ? "true" : "false")},\"mtv\":{XZ(r.MinimumTranslationVector)},\"normal\":{XZ(r.NormalAxis)},\"actionPoint\":{XZ(r.ActionPoint)}}}";

    private static string XZ(Vector3 v) => $"[{Number(v.X)},{Number(v.Z)}]";

    private static string Number(float v) => (v == 0f ? 0f : v).ToString(CultureInfo.InvariantCulture);

    private static (string Text, Shape Shape) RandomShape(Random random)
    {
        float x = F(random, -40, 40), z = F(random, -40, 40);
        switch (random.Next(5))
        {
            case 0:
                float r = F(random, 1, 30);
                return (Circle(x, z, r), new Circle(new Vector2(x, z), r));
            case 1:
                float w = F(random, 0, 40), h = F(random, 0, 40);
                return (Aabb(x, z, x + w, z + h), new Aabb(new Vector2(x, z), new Vector2(x + w, z + h)));
            case 2:
                float s = MathF.Sqrt(0.5f);
                float[] min = [x - 20, z - 20, ((x + z) * s) - 15, ((x - z) * s) - 15];
                float[] max = [x + 20, z + 20, ((x + z) * s) + 15, ((x - z) * s) + 15];
                return (KDop8(Array.ConvertAll(min, v => (double)v), Array.ConvertAll(max, v => (double)v)), new KDop8(min, max));
            case 3:
                // Points on a circle in angle order (one per quarter turn) form a convex quadrilateral.
                float radius = F(random, 5, 30);
                var quad = new Vector2[4];
                for (int k = 0; k < 4; k++)
                {
                    float angle = (k + F(random, 0.1, 0.9)) * MathF.PI / 2;
                    quad[k] = new Vector2(x + (radius * MathF.Cos(angle)), z + (radius * MathF.Sin(angle)));
                }

                return (Polygon(Array.ConvertAll(quad, v => ((double)v.X, (double)v.Y))), new ConvexPolygon(quad));
            default:
                float bx = x + F(random, -50, 50), bz = z + F(random, 1, 50);
                return (Segment(x, z, bx, bz), new Segment(new Vector2(x, z), new Vector2(bx, bz)));
        }
    }

    private static float F(Random random, double lo, double hi) => (float)(lo + ((hi - lo) * random.NextDouble()));
}
