using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using Xunit;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary><c>run --svg</c>: the final frame has fish and ball ids at their places, team colours and a legend.</summary>
public sealed class SvgFrameTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "urwpg-svg-" + Guid.NewGuid().ToString("N"));

    public SvgFrameTests() => Directory.CreateDirectory(_folder);

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void TheFinalFrameHasIdsColoursAndALegend()
    {
        string svg = Path.Combine(_folder, "f.svg"), trace = Path.Combine(_folder, "t.jsonl");
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

    private static string Num(float v)
    {
        string s = v.ToString("0.##", CultureInfo.InvariantCulture);
        return s == "-0" ? "0" : s;
    }
}
