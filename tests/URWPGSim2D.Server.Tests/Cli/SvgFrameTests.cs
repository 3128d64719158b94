using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary><c>run --svg</c>: the final frame has fish and ball ids at their places, team colours and a legend.</summary>
public sealed class SvgFrameTests() : TempFolderTest("urwpg-svg-")
{
    [Fact]
    public void TheFinalFrameHasIdsColoursAndALegend()
    {
        string svg = Path.Combine(Folder, "f.svg"), trace = Path.Combine(Folder, "t.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "40", "--svg", svg, "--trace", trace);
        Assert.Equal(0, run.ExitCode);
        string picture = File.ReadAllText(svg);
        var last = JsonDocument.Parse(File.ReadLines(trace).Last()).RootElement;

        // Legend: both teams with colour, strategy and goals; the ball and obstacle keys.
        Assert.Contains("fill=\"#d9483b\"", picture, StringComparison.Ordinal);
        Assert.Contains("fill=\"#2f6fd6\"", picture, StringComparison.Ordinal);
        Assert.Contains(">team 0 (chase-ball): 0</text>", picture, StringComparison.Ordinal);
        Assert.Contains(">team 1 (chase-ball): 0</text>", picture, StringComparison.Ordinal);
        Assert.Contains(">ball</text>", picture, StringComparison.Ordinal);
        Assert.Contains(">obstacle</text>", picture, StringComparison.Ordinal);

        // Each fish's eight leaves in its team's colour, its id 75 mm above its body centre.
        Assert.Equal(4 * 8, Regex.Count(picture, "<polygon[^>]*fill=\"#(d9483b|2f6fd6)\""));
        Assert.Equal(2 * 8, Regex.Count(picture, "<polygon[^>]*fill=\"#d9483b\""));
        var fish = last.GetProperty("fish");
        for (int i = 0; i < fish.GetArrayLength(); i++)
        {
            var p = fish[i].GetProperty("position");
            string at = $"x=\"{Num(p[0].GetSingle())}\" y=\"{Num(p[1].GetSingle() - 75)}\"";
            Assert.Matches($"<text {Regex.Escape(at)}[^>]*>fish{i}</text>", picture);
        }

        // Each ball's number at its centre.
        var balls = last.GetProperty("balls");
        for (int i = 0; i < balls.GetArrayLength(); i++)
        {
            var p = balls[i].GetProperty("position");
            string at = $"x=\"{Num(p[0].GetSingle())}\" y=\"{Num(p[1].GetSingle())}\"";
            Assert.Matches($"<text {Regex.Escape(at)}[^>]*>{i}</text>", picture);
        }
    }

    [Theory]
    [InlineData("survival")]
    [InlineData("rescue")]
    public void FishParkedOffThePoolAreInThePicture(string item)
    {
        // The item parks fish at z = 1591, outside the 4500 × 3000 pool: the view box grows to hold
        // every polygon of every fish (and their ids above them), still with the caption on top.
        string svg = Path.Combine(Folder, item + ".svg");
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--item", item, "--cycles", "0", "--svg", svg).ExitCode);
        var picture = System.Xml.Linq.XDocument.Load(svg).Root!;
        double[] box = [.. picture.Attribute("viewBox")!.Value.Split(' ').Select(v => double.Parse(v, CultureInfo.InvariantCulture))];
        var polygons = picture.Elements().Where(e => e.Name.LocalName == "polygon").ToList();
        Assert.NotEmpty(polygons);
        double lowest = double.NegativeInfinity;
        foreach (var polygon in polygons)
        {
            foreach (var point in polygon.Attribute("points")!.Value.Split(' ', StringSplitOptions.RemoveEmptyEntries))
            {
                double[] xy = [.. point.Split(',').Select(v => double.Parse(v, CultureInfo.InvariantCulture))];
                Assert.InRange(xy[0], box[0], box[0] + box[2]);
                Assert.InRange(xy[1], box[1], box[1] + box[3]);
                lowest = Math.Max(lowest, xy[1]);
            }
        }

        Assert.True(lowest > 1500, "a fish is parked below the pool");
        Assert.All(picture.Elements().Where(e => e.Name.LocalName == "text" && e.Value.StartsWith("fish", StringComparison.Ordinal)), t =>
        {
            Assert.InRange(double.Parse(t.Attribute("x")!.Value, CultureInfo.InvariantCulture), box[0], box[0] + box[2]);
            Assert.InRange(double.Parse(t.Attribute("y")!.Value, CultureInfo.InvariantCulture), box[1], box[1] + box[3]);
        });
    }

    [Fact]
    public void WithEveryBodyInThePoolThePictureIsThePoolAndItsCaption()
    {
        // Ball-grab's 3000 × 2000 pool: 20 mm each side, 170 above for the caption and legend, 20 below.
        string svg = Path.Combine(Folder, "ball-grab.svg");
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--cycles", "0", "--svg", svg).ExitCode);
        Assert.Contains("viewBox=\"-1520 -1170 3040 2190\"", File.ReadAllText(svg), StringComparison.Ordinal);
    }

    private static string Num(float v)
    {
        string s = v.ToString("0.##", CultureInfo.InvariantCulture);
        return s == "-0" ? "0" : s;
    }
}
