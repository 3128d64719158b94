using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// <c>tournament --check</c>: one line per entrant — whether it loads, and one match of at most a
/// minute against idle with its faults, slowest call and score — and nothing written.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class TournamentCheckTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-tour-check-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void Each_entrant_gets_a_line_the_class_can_read_before_the_real_run()
    {
        string dir = Path.Combine(_folder, "class");
        Directory.CreateDirectory(dir);
        File.WriteAllText(Path.Combine(dir, "good.cs"), """
            using System;
            using URWPGSim2D.Strategies;
            public sealed class Good : IStrategy
            {
                public string TeamName => "good";
                public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d) { for (int i = 0; i < d.Length; i++) d[i] = new Decision(6, 7); }
            }
            """);
        File.WriteAllText(Path.Combine(dir, "thrower.cs"), """
            using System;
            using URWPGSim2D.Strategies;
            public sealed class Thrower : IStrategy
            {
                public string TeamName => "thrower";
                public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d) { if (s.Cycle % 10 == 5) throw new InvalidOperationException("oops"); }
            }
            """);
        File.WriteAllText(Path.Combine(dir, "broken.cs"), "public class Broken {");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrants-dir", dir, "--entrant", "demo=demo", "--cycles", "6000", "--isolation", "none", "--strategy-timeout", "5000", "--check");
        Assert.True(run.ExitCode == 0, run.Stderr);
        string[] lines = run.Stdout.TrimEnd('\n').Split('\n');
        Assert.Equal("check: ball-grab, 4 entrants, each in one 600-cycle match against idle (seed 1)", lines[0]);
        Assert.StartsWith("entrant  ready  exceptions  timeouts  bad answers  host ends  slowest call  score  first fault or why not loaded", lines[1], StringComparison.Ordinal);
        Assert.Matches(@"^broken   no              0         0            0          0             -      0  not loaded: cannot compile ", lines[2]);
        Assert.Matches(@"^good     yes             0         0            0          0  +\d+ ms  +\d+  -$", lines[3]);
        Assert.Matches(@"^thrower  no             60         0            0          0  +\d+ ms  +\d+  cycle 6: InvalidOperationException: oops$", lines[4]);
        Assert.Matches(@"^demo     yes             0         0            0          0  +-  +\d+  -$", lines[5]);
        Assert.Equal("2 of 4 entrants ready", lines[6]);
        Assert.Empty(Directory.GetFileSystemEntries(_folder, "*", SearchOption.TopDirectoryOnly).AsSpan()[1..].ToArray()); // nothing written beside the class
    }
}
