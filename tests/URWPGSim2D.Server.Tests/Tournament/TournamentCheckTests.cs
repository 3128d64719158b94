using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// <c>tournament --check</c>: one line per entrant — whether it loads, and one match of at most a
/// minute against idle with its faults, slowest call and score — and nothing written.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class TournamentCheckTests() : TempFolderTest("urwpg-tour-check-")
{
    [Fact]
    public void Each_entrant_gets_a_line_the_class_can_read_before_the_real_run()
    {
        string dir = Path.Combine(Folder, "class");
        Directory.CreateDirectory(dir);
        WriteStrategy(dir, "good", "for (int i = 0; i < d.Length; i++) d[i] = new Decision(6, 7);");
        WriteStrategy(dir, "thrower", "if (s.Cycle % 10 == 5) throw new InvalidOperationException(\"oops\");");
        File.WriteAllText(Path.Combine(dir, "broken.cs"), "public class Broken {");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrants-dir", dir, "--entrant", "demo=demo", "--cycles", "6000", "--isolation", "none", "--strategy-timeout", "5000", "--check");
        Assert.True(run.ExitCode == 0, run.Stderr);
        string[] lines = run.Stdout.TrimEnd('\n').Split('\n');
        Assert.Equal("check: ball-grab, 4 entrants, each in one 600-cycle match against idle (seed 1)", lines[0]);
        Assert.StartsWith("entrant  ready  exceptions  timeouts  bad answers  host ends  slowest call    memory  score  first fault or why not loaded", lines[1], StringComparison.Ordinal);
        Assert.Matches(@"^broken   no              0         0            0          0             -         -      0  not loaded: cannot compile ", lines[2]);
        Assert.Matches(@"^good     yes             0         0            0          0  +\d+ ms         -  +\d+  -$", lines[3]);
        Assert.Matches(@"^thrower  no             60         0            0          0  +\d+ ms         -  +\d+  cycle 6: InvalidOperationException: oops$", lines[4]);
        Assert.Matches(@"^demo     yes             0         0            0          0  +-         -  +\d+  -$", lines[5]);
        Assert.Equal("2 of 4 entrants ready", lines[6]);
        Assert.Empty(Directory.GetFileSystemEntries(Folder, "*", SearchOption.TopDirectoryOnly).AsSpan()[1..].ToArray()); // nothing written beside the class
    }

    /// <summary>
    /// The memory column: the most memory each entrant's strategy host held at once, measured by the
    /// kernel for its sandbox. An entrant that fills and holds 300 MiB shows at least that much more
    /// than one that holds nothing; the built-ins, which run in the server's process, show <c>-</c>.
    /// </summary>
    [Fact]
    public void The_memory_column_shows_the_most_memory_each_entrants_host_held()
    {
        string dir = Path.Combine(Folder, "class");
        Directory.CreateDirectory(dir);
        WriteStrategy(dir, "lean", string.Empty);
        WriteStrategy(dir, "hog", """
            if (Held.Count > 0) return;
            for (int k = 0; k < 300; k++)
            {
                var block = new byte[1 << 20];
                for (int i = 0; i < block.Length; i += 4096) block[i] = 1; // every page touched: resident
                Held.Add(block);
            }
            """);
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrants-dir", dir, "--entrant", "idle=idle", "--cycles", "20", "--strategy-timeout", "20000", "--check");
        Assert.True(run.ExitCode == 0, run.Stderr);
        var memory = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string line in run.Stdout.Split('\n').Skip(2).SkipLast(2))
        {
            var m = Regex.Match(line, @"^(\w+) .* (\d+ MiB|-)  +\d+  ");
            Assert.True(m.Success, line);
            memory[m.Groups[1].Value] = m.Groups[2].Value;
        }

        Assert.Equal("-", memory["idle"]);
        long hog = long.Parse(memory["hog"].Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture);
        long lean = long.Parse(memory["lean"].Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture);
        Assert.True(lean > 0 && hog >= lean + 300, $"hog {hog} MiB, lean {lean} MiB:\n{run.Stdout}");
    }

    // DIR/NAME.cs: an SDK strategy named NAME whose Decide(s, fish, d) runs the body (Held: a list it may keep blocks in).
    private static void WriteStrategy(string dir, string name, string body) =>
        File.WriteAllText(Path.Combine(dir, name + ".cs"), SdkStrategy.Source("Strategy_" + name, name, body, "private static readonly List<byte[]> Held = new();", "using System; using System.Collections.Generic; using URWPGSim2D.Strategies;"));
}
