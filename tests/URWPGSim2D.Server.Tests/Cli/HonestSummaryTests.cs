using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>The summary tells what happened: the cycles really played, the halves, the seed, every file written.</summary>
public sealed class HonestSummaryTests() : TempFolderTest("urwpg-honest-")
{
    [Fact]
    public void AMatchPastNormalTimeSaysHowManyCyclesItPlayedAndItsHalves()
    {
        // Water polo with both demos level after normal time goes to extra time (and further).
        var run = CliRun.Of(string.Empty, "run", "--item", "polo-1v1", "--cycles", "300", "--seed", "5");
        Assert.Equal(0, run.ExitCode);
        string[] lines = run.Stdout.Split('\n');
        var match = Regex.Match(lines[0], @"^match: (?<played>[0-9]+) cycles, .*, seed 5$");
        Assert.True(match.Success, lines[0]);
        int played = int.Parse(match.Groups["played"].Value, System.Globalization.CultureInfo.InvariantCulture);
        int halfTimes = lines.Count(l => Regex.IsMatch(l, @"^  cycle ([0-9]+): half-time: ") && int.Parse(Regex.Match(l, "[0-9]+").Value, System.Globalization.CultureInfo.InvariantCulture) < 300);
        Assert.Equal(1, halfTimes); // half-time of normal time at cycle 150
        Assert.Equal(
            played == 300
                ? "item: polo-1v1 (水球1VS1), 2 x 1 fish, 300 cycles in 2 halves"
                : $"item: polo-1v1 (水球1VS1), 2 x 1 fish, normal time 300 cycles in 2 halves, {played} cycles played",
            lines[1]);
    }

    [Fact]
    public void EveryFileWrittenHasItsLine()
    {
        string trace = Path.Combine(Folder, "t.jsonl"), svg = Path.Combine(Folder, "f.svg"), html = Path.Combine(Folder, "m.html");
        var run = CliRun.Of(string.Empty, "run", "--cycles", "3", "--trace", trace, "--svg", svg, "--html", html);
        Assert.Equal(0, run.ExitCode);
        Assert.EndsWith($"strategy faults: none\nwrote {trace} (the trace)\nwrote {svg} (the final frame)\nwrote {html} (the replay page)\n", run.Stdout, StringComparison.Ordinal);
        Assert.True(File.Exists(trace) && File.Exists(svg) && File.Exists(html));
    }
}
