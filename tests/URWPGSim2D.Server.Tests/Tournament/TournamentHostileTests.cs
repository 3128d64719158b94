namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// A tournament writes a result for every match whatever its entrants do to their sandboxes, and a
/// match that fails inside the server is recorded as a forfeit of the team at fault, which a re-run keeps.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class TournamentHostileTests() : TempFolderTest("urwpg-tour-hostile-")
{
    private string Sdk(string name, string body) =>
        SdkStrategy.Write(Folder, name, name + "\\u001b[2J", "for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);\n" + body,
            usings: "using System; using System.IO; using System.Diagnostics; using System.Runtime.InteropServices; using URWPGSim2D.Strategies;");

    [Attack("faults", "it buries its scratch folder")]
    [Attack("faults", "it prints without end")]
    [Attack("sandbox", "processes")]
    [Fact]
    public void Entrants_that_fork_bury_flood_and_hoard_leave_every_result_written_and_a_clean_terminal()
    {
        string bomb = Sdk("Bomb", """
            if (s.Cycle != 1) return;
            try { for (int i = 0; i < 2000; i++) Process.Start(new ProcessStartInfo("/bin/sleep", "1000") { UseShellExecute = false, RedirectStandardOutput = true }); }
            catch (Exception e) { throw new Exception("\u001b]0;title\u0007 " + e.GetType().Name); }
            """);
        string burier = Sdk("Burier", """
            if (s.Cycle != 1) return;
            for (int i = 0; i < 100; i++) { Directory.CreateDirectory(new string('d', 200)); Directory.SetCurrentDirectory(new string('d', 200)); }
            """);
        string hog = Sdk("Hog", """
            if (s.Cycle != 1) return;
            var page = new byte[1 << 20];
            for (int i = 0; i < 8192; i++) { IntPtr p = Marshal.AllocHGlobal(1 << 20); Marshal.Copy(page, 0, p, page.Length); }
            """);
        string[] tour = ["tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "bomb=" + bomb, "--entrant", "burier=" + burier, "--entrant", "hog=" + hog,
            "--seeds", "1", "--cycles", "10", "--strategy-timeout", "60000", "--strategy-memory", "64", "--strategy-processes", "64", "--threads", "2", "--sandbox", "required", "--out", Path.Combine(Folder, "t")];
        var run = CliRun.Of(string.Empty, tour);
        Assert.True(run.ExitCode == 0, run.Stderr);
        string[] lines = File.ReadAllLines(Path.Combine(Folder, "t", "results.jsonl"));
        Assert.Equal(1 + 12, lines.Length); // header + 4 × 3 matches
        Assert.All(lines.Skip(1), l => Assert.StartsWith("{\"kind\":\"match\"", l, StringComparison.Ordinal));
        Assert.Contains(lines, l => l.Contains("out of memory: its sandbox reached its limit of 448 MiB", StringComparison.Ordinal));
        foreach (char c in run.Stdout + run.Stderr)
        {
            Assert.False(char.IsControl(c) && c != '\n', $"control character U+{(int)c:X4} in the output");
        }

        // Played again into the same folder: nothing left to play.
        var again = CliRun.Of(string.Empty, tour);
        Assert.True(again.ExitCode == 0, again.Stderr);
        Assert.Contains("0 to play, 12 already there", again.Stdout, StringComparison.Ordinal);
    }

    [Attack("faults", "a match fails inside the server itself")]
    [Fact]
    public void A_match_that_failed_inside_the_server_is_a_forfeit_of_the_team_at_fault_and_stands()
    {
        var header = new TournamentHeader("ball-grab", [new Entrant("a", "idle"), new Entrant("b", "idle")], 1, 1, 10, 100, 2);
        var runner = new TournamentRunner(URWPGSim2D.Engine.Items.Catalog.ItemRegistry.Find("ball-grab")!, header, null!, null);
        var match = new ScheduledMatch(1, 1, [1, 0]);
        var record = runner.Failed(match, new TeamFaultException(1, new IOException("disk on fire")));
        Assert.Equal(["b", "a"], record.Entrants);
        Assert.Equal([1], record.Forfeits);
        Assert.Equal(["the match failed inside the server: IOException: disk on fire"], record.Reasons);

        string file = Path.Combine(Folder, "results.jsonl");
        TournamentFile.Write(file, header, [record]);
        Assert.EndsWith("{\"kind\":\"forfeit\",\"index\":1,\"seed\":1,\"entrants\":[\"b\",\"a\"],\"forfeits\":[1],\"reasons\":[\"the match failed inside the server: IOException: disk on fire\"],\"failed\":true}", File.ReadAllLines(file)[^1], StringComparison.Ordinal);
        var read = Assert.Single(TournamentFile.Read(file).Records);
        Assert.True(read.Failed);

        // Both entrants load: a forfeit for want of loading would be played again, this one stands.
        var schedule = new TournamentSchedule(2, 2, 1, 1);
        Assert.True(TournamentResume.Stands(read, schedule, [null, null]));
        Assert.False(TournamentResume.Stands(read with { Failed = false }, schedule, [null, null]));

        // Without a team to put it on, every team of the match forfeits.
        Assert.Equal([0, 1], runner.Failed(match, new InvalidOperationException("lost")).Forfeits);
    }
}
