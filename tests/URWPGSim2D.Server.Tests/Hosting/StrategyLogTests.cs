#define DEBUG // Debug.WriteLine is this test's subject: compiled in Release builds of the tests too
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Teams;
using URWPGSim2D.Server.Tests.Trace;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// What a strategy prints (<c>run --strategy-log</c>) lands in the trace per team and cycle: from
/// its thread in the server's process and from a strategy host, bounded per cycle, and only with the option.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class StrategyLogTests() : TempFolderTest("urwpg-log-")
{
    private string Printer() => SdkStrategy.Write(Folder, "Printer", "printer", """
        Console.WriteLine($"saw cycle {s.Cycle}");
        Console.Error.Write("fish " + fish.Length);
        if (s.Cycle == 7)
        {
            Console.Write(new string('x', 10000));
        }

        for (int i = 0; i < d.Length; i++)
        {
            d[i] = new Decision(5, 7);
        }
        """);

    private static Dictionary<int, string> Logs(string trace, int team) =>
        File.ReadLines(trace).Select(l => JsonDocument.Parse(l).RootElement)
            .Where(l => l.TryGetProperty("log", out _))
            .ToDictionary(
                l => l.GetProperty("cycle").GetInt32(),
                l => l.GetProperty("log").EnumerateArray().Single(e => e.GetProperty("team").GetInt32() == team).GetProperty("text").GetString()!);

    [Fact]
    public void What_a_strategy_prints_is_in_the_trace_per_cycle_in_process_and_from_a_host()
    {
        var traces = new List<byte[]>();
        foreach (string isolation in new[] { "none", "process" })
        {
            string trace = Path.Combine(Folder, isolation + ".jsonl");
            var run = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "12", "--strategy", "0=" + Printer(), "--isolation", isolation,
                "--strategy-timeout", "5000", "--strategy-log", "--trace", trace);
            Assert.True(run.ExitCode == 0, run.Stderr);
            Assert.DoesNotContain("saw cycle", run.Stdout + run.Stderr, StringComparison.Ordinal);
            var logs = Logs(trace, 0);
            Assert.Equal(Enumerable.Range(1, 12), logs.Keys.Order());
            foreach (var (cycle, text) in logs)
            {
                if (cycle == 8)
                {
                    // The cycle that printed 10,000 more characters: the first 4,096 kept, the rest counted.
                    int kept = StrategyLog.MaxChars - $"saw cycle 7\nfish 2".Length;
                    Assert.Equal($"saw cycle 7\nfish 2{new string('x', kept)}\n… {10000 - kept} more characters dropped (at most 4096 a cycle)", text);
                }
                else
                {
                    Assert.Equal($"saw cycle {cycle - 1}\nfish 2", text); // decided from the previous cycle's snapshot
                }
            }

            traces.Add(File.ReadAllBytes(trace));
        }

        Assert.True(traces[0].AsSpan().SequenceEqual(traces[1]), "a hosted strategy's output differs from the same strategy's in process");
    }

    [Fact]
    public void Without_strategy_log_the_trace_has_no_log()
    {
        string trace = Path.Combine(Folder, "off.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "3", "--strategy", "0=" + Printer(), "--isolation", "process", "--trace", trace);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.DoesNotContain("\"log\"", File.ReadAllText(trace), StringComparison.Ordinal);
    }

    private sealed class DebugPrinter : IStrategy
    {
        public string TeamName => "debug printer";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            Debug.WriteLine($"debug {snapshot.Cycle}");
            decisions.Fill(Decision.Stop);
        }
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Debug_output_of_a_strategy_call_is_its_teams_and_only_its(bool isolated)
    {
        var teams = new TeamStrategy?[] { new("debug", new DebugPrinter(), isolated), null };
        var match = MatchBuilder.BuildRecording(DefaultScenario.Load(), teams, strategyTimeoutMs: 5000, strategyLog: true);
        var sink = new TraceBytes();
        using (var loop = new MatchLoop(match, 3, sink))
        {
            Debug.WriteLine("the server's own debug line"); // not a strategy call's: no team's log
            loop.Play();
        }

        var lines = System.Text.Encoding.UTF8.GetString(sink.ToArray()).Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => JsonDocument.Parse(l).RootElement).ToArray();
        for (int n = 1; n <= 3; n++)
        {
            var log = Assert.Single(lines[n].GetProperty("log").EnumerateArray());
            Assert.Equal(0, log.GetProperty("team").GetInt32());
            Assert.Equal($"debug {n - 1}\n", log.GetProperty("text").GetString());
        }
    }
}
