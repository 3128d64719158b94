using System.Globalization;
using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Packaging;

/// <summary>
/// The original-API template's strategy (templates/Strategy/Strategy.cs, compiled by the server as a
/// team's source) plays ball-grab: against idle it scores on most seeds, with the real engine.
/// </summary>
public sealed partial class OriginalTemplatePlayTests
{
    [Fact]
    public void TheTemplateScoresInBallGrabAgainstIdleOnMostSeeds()
    {
        string source = Docs.Repository.PathOf("templates/Strategy/Strategy.cs");
        var run = CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--seed", "1", "--batch", "10", "--threads", "2",
            "--strategy", "0=" + source, "--strategy", "1=idle", "--strategy-timeout", "5000"); // a generous deadline: no time-out on a busy machine changes a match
        Assert.True(run.ExitCode == 0, run.Stderr);
        var matches = MatchLine().Matches(run.Stdout);
        Assert.Equal(10, matches.Count);
        int scored = 0;
        foreach (Match m in matches)
        {
            Assert.Equal(0, int.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture));
            if (int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture) > 0)
            {
                scored++;
            }
        }

        // Seeds 1 to 10 score on 8 (goals 3 1 0 4 6 3 0 7 1 3); most is at least 7.
        Assert.True(scored >= 7, run.Stdout);
    }

    [GeneratedRegex(@"^match \d+ \(seed \d+\): score (\d+)-(\d+),", RegexOptions.Multiline)]
    private static partial Regex MatchLine();
}
