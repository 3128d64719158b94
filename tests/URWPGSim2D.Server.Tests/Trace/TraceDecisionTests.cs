namespace URWPGSim2D.Server.Tests.Trace;

/// <summary>
/// Each fish's <c>decision</c> (VCode, TCode) and <c>gears</c> (the codes its speed and turn rate are
/// at) on every cycle line after cycle 0: the decision is the one its strategy gave for that cycle,
/// in process and from a strategy host, and the gears reach a decision that is held.
/// </summary>
public sealed class TraceDecisionTests() : TempFolderTest("urwpg-decision-")
{
    // Decides (VCode, TCode) from the cycle it sees and the fish's index: a known answer for every line.
    private string Strategy() => SdkStrategy.Write(Folder, "Pattern", "pattern", """
        for (int i = 0; i < d.Length; i++)
        {
            d[i] = s.Cycle < 60 ? new Decision(10, 3) : new Decision((s.Cycle + fish[i]) % 15, ((s.Cycle * 4) + fish[i]) % 15);
        }
        """);

    [Theory]
    [InlineData("none")]
    [InlineData("process")]
    public void Every_fish_carries_the_decision_its_strategy_gave_for_the_cycle_and_its_gear_codes(string isolation)
    {
        string trace = Path.Combine(Folder, isolation + ".jsonl");
        var run = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "120", "--strategy", "0=" + Strategy(), "--strategy", "1=" + Strategy(),
            "--isolation", isolation, "--strategy-timeout", "5000", "--trace", trace);
        Assert.True(run.ExitCode == 0, run.Stderr);
        var lines = File.ReadLines(trace).Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray();
        Assert.Equal(121, lines.Length);
        Assert.All(lines[0].GetProperty("fish").EnumerateArray(), f => Assert.False(f.TryGetProperty("decision", out _) || f.TryGetProperty("gears", out _), "cycle 0 has no decision"));
        for (int n = 1; n < lines.Length; n++)
        {
            var fish = lines[n].GetProperty("fish");
            for (int i = 0; i < fish.GetArrayLength(); i++)
            {
                // Line n is cycle n, decided from the snapshot of line n - 1.
                int seen = n - 1;
                (int v, int t) expected = seen < 60 ? (10, 3) : ((seen + i) % 15, ((seen * 4) + i) % 15);
                var decision = fish[i].GetProperty("decision");
                Assert.Equal(expected, (decision[0].GetInt32(), decision[1].GetInt32()));
                var gears = fish[i].GetProperty("gears");
                Assert.Equal(2, gears.GetArrayLength());
                Assert.InRange(gears[0].GetInt32(), 0, 15);
                Assert.InRange(gears[1].GetInt32(), 0, 14);
                if (n >= 45 && n <= 60)
                {
                    // (10, 3) held from cycle 1: the gear approach has reached both codes (0.9^k of the gap left), and the speed its table value.
                    Assert.Equal((10, 3), (gears[0].GetInt32(), gears[1].GetInt32()));
                }
                else if (n == 1)
                {
                    Assert.Equal(0, gears[0].GetInt32()); // one step from rest is a tenth of the way
                }
            }
        }
    }
}
