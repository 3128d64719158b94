using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// One analytic case for each unordered pair of the five shape kinds, worked out by hand
/// (the expected MTV, normal and action point follow from the geometry, not from the library),
/// run in both orders: swapping a and b negates the MTV and the normal and keeps the action point.
/// </summary>
public sealed class CollideGoldenTests
{
    private const double Tolerance = 1e-4;
    private static readonly double S = Math.Sqrt(0.5);

    public static TheoryData<string, string, string, double[]> KindPairs()
    {
        var data = new TheoryData<string, string, string, double[]>();

        // Expected values: mtv x, z, normal x, z, action point x, z.
        // Circle r 10 at the origin against a circle r 10 at (16, 0): overlap x ∈ [6, 10].
        data.Add("circle-circle", Circle(0, 0, 10), Circle(16, 0, 10), [-4, 0, -1, 0, 8, 0]);

        // Box below the circle: nearest face z = 7, overlap z ∈ [7, 10] on the centre line.
        data.Add("circle-aabb", Circle(0, 0, 10), Aabb(-5, 7, 5, 20), [0, -3, 0, -1, 0, 8.5]);

        // Diamond (8,0)(18,10)(28,0)(18,−10); the circle at (8, −10) is 5√2 from the face x + z = 8
        // (foot (13, −5) inside the edge); overlap on the centre line t ∈ [−10, −5√2] along −(√½, √½).
        double ckDepth = 10 - (5 * Math.Sqrt(2));
        double ckT = -(10 + (5 * Math.Sqrt(2))) / 2;
        data.Add("circle-kdop8", Circle(8, -10, 10), Diamond(18, 0, 10),
            [-S * ckDepth, -S * ckDepth, -S, -S, 8 - (ckT * S), -10 - (ckT * S)]);

        // Triangle given clockwise; nearest edge x = 8.
        data.Add("circle-polygon", Circle(0, 0, 10), Polygon((8, -10), (8, 10), (30, 0)), [-2, 0, -1, 0, 9, 0]);

        // Segment x = 6: depth 4, the segment covers the single point (6, 0) of the centre line.
        data.Add("circle-segment", Circle(0, 0, 10), Segment(6, -20, 6, 20), [-4, 0, -1, 0, 6, 0]);

        // Boxes overlapping in [8, 10] × [2, 6]: least push 2 along −x; centroid (9, 4).
        data.Add("aabb-aabb", Aabb(0, 0, 10, 10), Aabb(8, 2, 20, 6), [-2, 0, -1, 0, 9, 4]);

        // Diamond centred (14, 5), half-diagonal 6: the overlap is the triangle (8,5)(10,3)(10,7).
        data.Add("aabb-kdop8", Aabb(0, 0, 10, 10), Diamond(14, 5, 6), [-2, 0, -1, 0, 28.0 / 3, 5]);

        // Triangle with its apex (8, 5) 2 inside the box's side x = 10 (the reference face): the
        // action point is half way from the apex to that face.
        data.Add("aabb-polygon", Aabb(0, 0, 10, 10), Polygon((8, 5), (20, -1), (20, 11)), [-2, 0, -1, 0, 9, 5]);

        // Segment z = 9 across the box: least push 1 along −z; the overlap is x ∈ [0, 10] on z = 9.
        data.Add("aabb-segment", Aabb(0, 0, 10, 10), Segment(-5, 9, 20, 9), [0, -1, 0, -1, 5, 9]);

        // Diamonds at the origin and at (8, 8), half-diagonal 10: x + z ∈ [6, 10] overlaps by 2√2
        // along −(√½, √½); the overlap is the rectangle 6 ≤ x + z ≤ 10, |x − z| ≤ 10, centroid (4, 4).
        data.Add("kdop8-kdop8", Diamond(0, 0, 10), Diamond(8, 8, 10), [-2, -2, -S, -S, 4, 4]);

        // Square [8, 20] × [−3, 3] against the diamond: the diamond's tip (10, 0) is 2 inside the
        // square's side x = 8 (the reference face): action point half way, (9, 0).
        data.Add("kdop8-polygon", Diamond(0, 0, 10), Polygon((8, -3), (20, -3), (20, 3), (8, 3)), [-2, 0, -1, 0, 9, 0]);

        // Segment x = 8 through the diamond: overlap z ∈ [−2, 2].
        data.Add("kdop8-segment", Diamond(0, 0, 10), Segment(8, -20, 8, 20), [-2, 0, -1, 0, 8, 0]);

        // Square polygon against the triangle of aabb-polygon.
        data.Add("polygon-polygon", Polygon((0, 0), (10, 0), (10, 10), (0, 10)), Polygon((8, 5), (20, 11), (20, -1)), [-2, 0, -1, 0, 9, 5]);

        // Triangle x, z ≥ 0, x + z ≤ 10 cut by x = 6 (z ∈ [0, 4]): least push 4 along −x.
        data.Add("polygon-segment", Polygon((0, 0), (10, 0), (0, 10)), Segment(6, -5, 6, 20), [-4, 0, -1, 0, 6, 2]);

        // Crossing at (2, 0); pushing a by 1 along −z clears b's lower end.
        data.Add("segment-segment", Segment(0, 0, 10, 0), Segment(2, -1, 2, 9), [0, -1, 0, -1, 2, 0]);
        return data;
    }

    [Theory]
    [MemberData(nameof(KindPairs))]
    public void EachKindPairMatchesTheGeometry(string name, string a, string b, double[] expected)
    {
        var run = CliRun.Collide(Pairs(Pair(a, b), Pair(b, a)));

        Assert.True(run.ExitCode == 0, $"{name}: {run.Stderr}");
        Assert.Equal(string.Empty, run.Stderr);
        using var doc = JsonDocument.Parse(run.Stdout);
        var results = doc.RootElement;
        Assert.Equal(2, results.GetArrayLength());
        AssertResult(name + " (a, b)", results[0], expected, sign: 1);
        AssertResult(name + " (b, a)", results[1], expected, sign: -1);
    }

    [Fact]
    public void ExactOutputForHandWorkedCircles()
    {
        // r 10 at (0,0) and (16,0): depth 4 along −x, overlap x ∈ [6, 10].
        // r 3 at (0,0) and (3,4): d = 5, depth 1 along (−3/5, −4/5), overlap t ∈ [2, 3] from (3, 4).
        // r 10 at (0,0) and (20,0): touching, which is not intersecting.
        var run = CliRun.Collide(Pairs(
            Pair(Circle(0, 0, 10), Circle(16, 0, 10)),
            Pair(Circle(0, 0, 3), Circle(3, 4, 3)),
            Pair(Circle(0, 0, 10), Circle(20, 0, 10))));

        Assert.Equal(0, run.ExitCode);
        Assert.Equal(string.Empty, run.Stderr);
        Assert.Equal(
            "[{\"intersect\":true,\"mtv\":[-4,0],\"normal\":[-1,0],\"actionPoint\":[8,0]}," +
            "{\"intersect\":true,\"mtv\":[-0.6,-0.8],\"normal\":[-0.6,-0.8],\"actionPoint\":[1.5,2]}," +
            "{\"intersect\":false,\"mtv\":[0,0],\"normal\":[0,0],\"actionPoint\":[0,0]}]\n",
            run.Stdout);
    }

    [Fact]
    public void SeparatedShapesOfEveryKindGiveZeros()
    {
        string[] shapes = [Circle(0, 0, 1), Aabb(-1, -1, 1, 1), Diamond(0, 0, 1), Polygon((-1, 0), (1, 0), (0, 1)), Segment(-1, 0, 1, 0)];
        string[] far = [Circle(100, 0, 1), Aabb(99, -1, 101, 1), Diamond(100, 0, 1), Polygon((99, 0), (101, 0), (100, 1)), Segment(99, 0, 101, 0)];
        var pairs = new List<string>();
        foreach (var a in shapes)
        {
            foreach (var b in far)
            {
                pairs.Add(Pair(a, b));
            }
        }

        var run = CliRun.Collide(Pairs([.. pairs]));

        Assert.Equal(0, run.ExitCode);
        const string apart = "{\"intersect\":false,\"mtv\":[0,0],\"normal\":[0,0],\"actionPoint\":[0,0]}";
        Assert.Equal("[" + string.Join(",", System.Linq.Enumerable.Repeat(apart, 25)) + "]\n", run.Stdout);
    }

    private static void AssertResult(string name, JsonElement result, double[] expected, int sign)
    {
        Assert.True(result.GetProperty("intersect").GetBoolean(), name);
        double[] actual =
        [
            .. Pair2(result, "mtv"), .. Pair2(result, "normal"), .. Pair2(result, "actionPoint"),
        ];
        double[] wanted = [sign * expected[0], sign * expected[1], sign * expected[2], sign * expected[3], expected[4], expected[5]];
        for (int i = 0; i < 6; i++)
        {
            Assert.True(Math.Abs(actual[i] - wanted[i]) <= Tolerance, $"{name}: component {i} is {actual[i]}, expected {wanted[i]}");
        }

        Assert.Equal(["intersect", "mtv", "normal", "actionPoint"], PropertyNames(result));
    }

    private static double[] Pair2(JsonElement result, string name)
    {
        var v = result.GetProperty(name);
        Assert.Equal(2, v.GetArrayLength());
        return [v[0].GetDouble(), v[1].GetDouble()];
    }

    private static List<string> PropertyNames(JsonElement result)
    {
        var names = new List<string>();
        foreach (var p in result.EnumerateObject())
        {
            names.Add(p.Name);
        }

        return names;
    }
}
