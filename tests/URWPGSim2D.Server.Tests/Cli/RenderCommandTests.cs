using System.Xml.Linq;
using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <c>render</c>: the SVG is well-formed XML with the expected elements (selected by class) at
/// the library's coordinates, fits its view box, is deterministic, and is written whole or not at all.
/// </summary>
public sealed class RenderCommandTests() : TempFolderTest("urwpgsim2d-render-")
{
    private const string RenderUsage = "Usage: urwpgsim2d render FILE --svg OUT";
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact]
    public void AFishShowsItsLeavesTheirEightDopsAndItsThreeTreeCircles()
    {
        var svg = Render(Shapes(Fish(30, -20, 0.6, 0.4, -0.3, 0.5)));
        var model = new FishModel(FishSize.Default, new FishPose(new Vector2(30, -20), 0.6f, 0.4f, -0.3f, 0.5f));

        Assert.Equal(Svg + "svg", svg.Root!.Name);
        Assert.Equal(
            new Dictionary<string, int> { ["background"] = 1, ["leaf"] = 8, ["kdop"] = 8, ["body-group"] = 1, ["tail-group"] = 1, ["root"] = 1, ["label"] = 1 },
            CountsOutsideTheLegend(svg));
        var leaves = ByClass(svg, "leaf").ToList();
        var kdops = ByClass(svg, "kdop").ToList();
        for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
        {
            AssertPoints(model.GetLeaf(part), leaves[(int)part], $"leaf {part}");
            AssertPoints(model.GetLeafBound(part).Vertices, kdops[(int)part], $"8-DOP {part}");
        }

        AssertCircle(model.Root, Assert.Single(ByClass(svg, "root")));
        AssertCircle(model.BodyGroup, Assert.Single(ByClass(svg, "body-group")));
        AssertCircle(model.TailGroup, Assert.Single(ByClass(svg, "tail-group")));
        Assert.Equal("shapes[0]", Assert.Single(ByClass(svg, "label")).Value);
    }

    [Fact]
    public void AnIntersectingFishBallPairShowsItsMtvNormalAndActionPoint()
    {
        // The hand-checked contact of CollideFishTests: mtv [0, 2], normal [0, 1], action point (70, −21.5).
        var svg = Render(Pairs(Pair(Fish(0, 0, 0), Circle(70, -78.5, 58)), Pair(Circle(1000, 0, 10), Circle(1100, 0, 10))));

        Assert.Equal(
            new Dictionary<string, int>
            {
                ["background"] = 1, ["leaf"] = 8, ["kdop"] = 8, ["body-group"] = 1, ["tail-group"] = 1, ["root"] = 1, ["shape"] = 3, ["outer"] = 3,
                ["normal"] = 1, ["mtv"] = 1, ["action-point"] = 1, ["annotation"] = 1, ["label"] = 4,
            },
            CountsOutsideTheLegend(svg));
        var point = Assert.Single(ByClass(svg, "action-point"));
        Assert.Equal((70.0, -21.5), (Number(point, "cx"), Number(point, "cy")));
        var mtv = PathPoints(Assert.Single(ByClass(svg, "mtv")));
        Assert.Equal([(70.0, -21.5), (70.0, -19.5)], mtv.Take(2));
        var normal = PathPoints(Assert.Single(ByClass(svg, "normal")));
        Assert.Equal((70.0, -21.5), normal[0]);
        Assert.Equal(70.0, normal[1].X, 3);
        Assert.True(normal[1].Z > -21.5 + 10, "the normal points along +z, from the ball toward the fish");
        Assert.Equal("pairs[0]: mtv [0, 2], parts body / -", Assert.Single(ByClass(svg, "annotation")).Value);
        Assert.Equal(["pairs[0].b", "pairs[0].a", "pairs[1].b", "pairs[1].a"], ByClass(svg, "label").Select(e => e.Value));
        var legend = Assert.Single(svg.Descendants(Svg + "g"), g => (string?)g.Attribute("class") == "legend");
        string legendText = string.Join("|", legend.Descendants(Svg + "text").Select(t => t.Value));
        foreach (var entry in new[] { "a (moved by the MTV)", "b", "leaf 8-DOP", "root circle", "body group circle", "tail group circle", "outer circle", "MTV", "normal", "action point", "+X right, +Z down" })
        {
            Assert.Contains(entry, legendText, StringComparison.Ordinal);
        }
    }

    [Fact]
    public void PairsThatDoNotIntersectHaveNoArrows()
    {
        var svg = Render(Pairs(Pair(Fish(0, 0, 0), Circle(500, 0, 58))));

        Assert.Empty(ByClass(svg, "mtv"));
        Assert.Empty(ByClass(svg, "normal"));
        Assert.Empty(ByClass(svg, "action-point"));
        Assert.Equal(8, ByClass(svg, "leaf").Count());
    }

    [Fact]
    public void TheViewBoxHoldsEverythingDrawnWithAMargin()
    {
        var svg = Render(Shapes(Fish(-300, 200, 2.5, 0.5, 0.9, -0.7), Polygon((400, 0), (500, 40), (450, 120)), Segment(-200, -300, 100, -250), Diamond(0, 0, 40), Aabb(200, 200, 260, 230)));

        double[] box = [.. svg.Root!.Attribute("viewBox")!.Value.Split(' ').Select(v => double.Parse(v, CultureInfo.InvariantCulture))];
        var points = new List<(double X, double Z)>();
        foreach (var e in svg.Descendants().Where(e => (string?)e.Attribute("class") is "leaf" or "kdop" or "shape" or "outer" or "root" or "body-group" or "tail-group"))
        {
            if (e.Name == Svg + "circle")
            {
                double cx = Number(e, "cx"), cy = Number(e, "cy"), r = Number(e, "r");
                points.AddRange([(cx - r, cy - r), (cx + r, cy + r)]);
            }
            else if (e.Name == Svg + "line")
            {
                points.AddRange([(Number(e, "x1"), Number(e, "y1")), (Number(e, "x2"), Number(e, "y2"))]);
            }
            else
            {
                points.AddRange(Points(e));
            }
        }

        double minX = points.Min(p => p.X), maxX = points.Max(p => p.X), minZ = points.Min(p => p.Z), maxZ = points.Max(p => p.Z);
        double margin = 0.05 * Math.Max(maxX - minX, maxZ - minZ);
        Assert.InRange(minX - box[0], margin, double.MaxValue);
        Assert.InRange(minZ - box[1], margin, double.MaxValue);
        Assert.InRange(box[0] + box[2] - maxX, margin, double.MaxValue);
        Assert.InRange(box[1] + box[3] - maxZ, margin, double.MaxValue);

        // Pixel size keeps the view box's aspect ratio.
        double width = Number(svg.Root, "width"), height = Number(svg.Root, "height");
        Assert.Equal(box[2] / box[3], width / height, 3);
    }

    [Fact]
    public void TheOutputIsDeterministicAndCultureInvariant()
    {
        string input = Pairs(Pair(Fish(12.5, -7.25, 0.3, 0.2, 0.1, -0.4), Circle(120, 10, 58)));
        string first = RenderText(input);
        string second = RenderText(input);
        var culture = CultureInfo.CurrentCulture;
        string german;
        try
        {
            // A culture writing numbers the German way (the machine may only have the invariant culture).
            var commas = (CultureInfo)CultureInfo.InvariantCulture.Clone();
            commas.NumberFormat.NumberDecimalSeparator = ",";
            commas.NumberFormat.NumberGroupSeparator = ".";
            commas.NumberFormat.NegativeSign = "\u2212";
            CultureInfo.CurrentCulture = commas;
            Assert.Equal("\u22121,5", (-1.5f).ToString(CultureInfo.CurrentCulture));
            german = RenderText(input);
        }
        finally
        {
            CultureInfo.CurrentCulture = culture;
        }

        Assert.Equal(first, second);
        Assert.Equal(first, german);
        Assert.Matches(@"viewBox=""-?\d+(\.\d+)? -?\d+(\.\d+)? \d+(\.\d+)? \d+(\.\d+)?""", first);
    }

    [Fact]
    public void DashWritesTheSvgToStandardOutput()
    {
        string input = Shapes(Circle(0, 0, 10));
        string file = Path.Combine(Folder, "c.svg");

        var toFile = CliRun.Of(input, "render", "-", "--svg", file);
        var toStdout = CliRun.Of(input, "render", "--svg", "-", "-");

        Assert.Equal((0, string.Empty, string.Empty), (toFile.ExitCode, toFile.Stdout, toFile.Stderr));
        Assert.Equal((0, string.Empty), (toStdout.ExitCode, toStdout.Stderr));
        Assert.Equal(File.ReadAllText(file), toStdout.Stdout);
    }

    [Fact]
    public void ASuccessfulRenderReplacesTheFileAndLeavesNoTemporary()
    {
        string file = Path.Combine(Folder, "out.svg");
        File.WriteAllText(file, "old");

        var run = CliRun.Of(Shapes(Fish(0, 0, 0)), "render", "-", "--svg", file);

        Assert.Equal((0, string.Empty, string.Empty), (run.ExitCode, run.Stdout, run.Stderr));
        Assert.StartsWith("<svg xmlns=\"http://www.w3.org/2000/svg\"", File.ReadAllText(file), StringComparison.Ordinal);
        Assert.Equal([file], Directory.GetFiles(Folder));
    }

    public static TheoryData<string, string> BadInputs() => new()
    {
        { Shapes(Fish(0, 0, 0), """{"type":"fish","position":[0,0],"heading":0,"joints":[0,0]}"""), "shapes[1].joints: must be an array of 3 numbers [φ1, φ2, φ3], got 2" },
        { Pairs(Pair(Fish(0, 0, 0, size: [160, 0, 30, 88, 66, 55]), Circle(0, 0, 1))), "pairs[0].a.size.width: must be > 0, got 0" },
        { Pairs(Pair(Circle(0, 0, 1), Circle(0, 0, -5))), "pairs[0].b.radius: must be > 0, got -5" },
        { "[{\"a\":" + Circle(0, 0, 1) + "}]", "pairs[0].b: required field is missing or null" },
        { "[{}]", "shapes[0].type: required field is missing or null" },
        { "", "shapes: input is empty" },
        { "[", "shapes[0]: malformed JSON at line 1, column 2: Expected depth to be zero at the end of the JSON payload. There is an open JSON object or array that should be closed." },
    };

    [Theory]
    [MemberData(nameof(BadInputs))]
    public void BadInputIsOneLineAndWritesNothing(string input, string expected)
    {
        string existing = Path.Combine(Folder, "existing.svg");
        string fresh = Path.Combine(Folder, "fresh.svg");
        File.WriteAllText(existing, "old");

        var overExisting = CliRun.Of(input, "render", "-", "--svg", existing);
        var toFresh = CliRun.Of(input, "render", "-", "--svg", fresh);

        CollideErrorTests.AssertOneLineFailure(overExisting, expected);
        CollideErrorTests.AssertOneLineFailure(toFresh, expected);
        Assert.Equal("old", File.ReadAllText(existing));
        Assert.Equal([existing], Directory.GetFiles(Folder));
    }

    [Fact]
    public void AnOutputThatCannotBeWrittenIsOneLineWithExitCodeTwo()
    {
        string file = Path.Combine(Folder, "no-such-dir", "out.svg");

        var run = CliRun.Of(Shapes(Circle(0, 0, 1)), "render", "-", "--svg", file);

        Assert.Equal((2, string.Empty), (run.ExitCode, run.Stdout));
        Assert.StartsWith(file + ": cannot write file: ", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
        Assert.Empty(Directory.GetFileSystemEntries(Folder));
    }

    [Theory]
    [InlineData(new[] { "render" }, "render: expected one FILE argument (- for stdin), got 0")]
    [InlineData(new[] { "render", "in.json" }, "render: --svg OUT is required")]
    [InlineData(new[] { "render", "--svg", "o.svg" }, "render: expected one FILE argument (- for stdin), got 0")]
    [InlineData(new[] { "render", "a.json", "b.json", "--svg", "o.svg" }, "render: expected one FILE argument (- for stdin), got 2")]
    [InlineData(new[] { "render", "a.json", "--svg" }, "render: --svg needs a file name (- for stdout)")]
    [InlineData(new[] { "render", "a.json", "--svg", "" }, "render: --svg needs a file name (- for stdout)")]
    [InlineData(new[] { "render", "a.json", "--svg", "x.svg", "--svg", "y.svg" }, "render: --svg given twice")]
    [InlineData(new[] { "render", "a.json", "--png", "x.png" }, "render: unknown option \"--png\"")]
    [InlineData(new[] { "render", "", "--svg", "x.svg" }, "render: FILE is empty")]
    public void WrongArgumentsGiveOneUsageLine(string[] args, string message)
    {
        CollideErrorTests.AssertOneLineFailure(CliRun.Of("[]", args), message + ". " + RenderUsage);
    }

    [Fact]
    public void AnEmptyArrayGivesAPictureWithOnlyTheLegend()
    {
        var svg = Render("[]");

        Assert.Equal(new Dictionary<string, int> { ["background"] = 1 }, CountsOutsideTheLegend(svg));
    }

    private XDocument Render(string input) => XDocument.Parse(RenderText(input));

    private string RenderText(string input)
    {
        string file = Path.Combine(Folder, "figure.svg");
        var run = CliRun.Of(input, "render", "-", "--svg", file);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Equal((string.Empty, string.Empty), (run.Stdout, run.Stderr));
        return File.ReadAllText(file);
    }

    private static IEnumerable<XElement> ByClass(XDocument svg, string cls) =>
        svg.Descendants().Where(e => (string?)e.Attribute("class") == cls);

    private static Dictionary<string, int> CountsOutsideTheLegend(XDocument svg) =>
        svg.Root!.Elements().Where(e => e.Name != Svg + "g").GroupBy(e => (string?)e.Attribute("class") ?? "(none)").ToDictionary(g => g.Key, g => g.Count());

    private static double Number(XElement e, string attribute) => double.Parse(e.Attribute(attribute)!.Value, CultureInfo.InvariantCulture);

    private static List<(double X, double Z)> Points(XElement polygon) =>
        [.. polygon.Attribute("points")!.Value.Split(' ').Select(p => p.Split(',')).Select(p => (double.Parse(p[0], CultureInfo.InvariantCulture), double.Parse(p[1], CultureInfo.InvariantCulture)))];

    // The points of a path "M x y L x y M ...", in order.
    private static List<(double X, double Z)> PathPoints(XElement path)
    {
        var numbers = path.Attribute("d")!.Value.Split(' ').Where(t => t is not ("M" or "L" or "Z")).Select(t => double.Parse(t, CultureInfo.InvariantCulture)).ToList();
        return [.. Enumerable.Range(0, numbers.Count / 2).Select(i => (numbers[2 * i], numbers[(2 * i) + 1]))];
    }

    private static void AssertPoints(ReadOnlySpan<Vector2> expected, XElement polygon, string what)
    {
        var actual = Points(polygon);
        Assert.True(expected.Length == actual.Count, $"{what}: {actual.Count} points, expected {expected.Length}");
        for (int i = 0; i < expected.Length; i++)
        {
            Assert.True(Math.Abs(expected[i].X - actual[i].X) <= 6e-4 && Math.Abs(expected[i].Y - actual[i].Z) <= 6e-4, $"{what} point {i}: {actual[i]} vs {expected[i]}");
        }
    }

    private static void AssertCircle(Collision.Shapes.Circle expected, XElement circle)
    {
        Assert.Equal(expected.Center.X, Number(circle, "cx"), 0.0006);
        Assert.Equal(expected.Center.Y, Number(circle, "cy"), 0.0006);
        Assert.Equal(expected.Radius, Number(circle, "r"), 0.0006);
    }
}
