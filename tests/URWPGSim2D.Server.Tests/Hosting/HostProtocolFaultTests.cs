namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Bad answers over the strategy protocol, end to end: a strategy writes its own lines into its host's
/// standard output (the protocol's channel to the server) in cycle 3, ahead of the host's real answer.
/// The server reads that line as the cycle's answer and charges it as docs/protocol.md says: a bad
/// answer for garbage, another cycle's number, a cut-short line, too many decisions (decisions for
/// fish the team does not have) or a gear out of range; a bad answer and the host's end for a line
/// over the limit. The host's real answer, left behind, is skipped, so one bad line costs exactly
/// one cycle; the match is always played to its end. Lockstep makes the order of the lines certain.
/// </summary>
public sealed class HostProtocolFaultTests() : TempFolderTest("urwpg-protocol-fault-")
{
    private string Strategy(string name, string line, string after = "")
    {
        string file = Path.Combine(Folder, name + ".cs");
        File.WriteAllText(file, "using System; using System.IO; using System.Text; using URWPGSim2D.Strategies;\n" + $$"""
            public sealed class {{name}} : IStrategy
            {
                private static readonly Stream Channel = Console.OpenStandardOutput();
                public string TeamName => "{{name}}";
                public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
                {
                    for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);
                    if (s.Cycle != 2) return;
                    byte[] bytes = Encoding.UTF8.GetBytes({{line}});
                    Channel.Write(bytes, 0, bytes.Length);
                    Channel.Flush();
                    {{after}}
                }
            }
            """);
        return file;
    }

    private static string Faults(CliRun run)
    {
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.StartsWith("match: 8 cycles,", run.Stdout, StringComparison.Ordinal);
        int at = run.Stdout.IndexOf("  team 0 (", StringComparison.Ordinal);
        Assert.True(at >= 0, "no fault line for team 0:\n" + run.Stdout);
        string line = run.Stdout[at..].Split('\n')[0];
        return line[(line.IndexOf("): ", StringComparison.Ordinal) + 3)..];
    }

    private CliRun Run(string spec) =>
        CliRun.Of(string.Empty, "run", "--cycles", "8", "--strategy", "0=" + spec, "--strategy-timeout", "1000", "--sandbox", "required");

    [Attack("faults", "it answers something unusable")]
    [Theory]
    [InlineData("Garbage", "\"this is not JSON\\n\"", "first: cycle 3: ")]
    [InlineData("WrongCycle", "\"{\\\"type\\\":\\\"decisions\\\",\\\"cycle\\\":99,\\\"decisions\\\":[[1,7],[1,7]]}\\n\"", "first: cycle 3: cycle: answered cycle 99, expected 2")]
    [InlineData("OtherFish", "\"{\\\"type\\\":\\\"decisions\\\",\\\"cycle\\\":2,\\\"decisions\\\":[[15,0],[15,0],[15,0],[15,0]]}\\n\"", "first: cycle 3: decisions: 4 for 2 fish")]
    [InlineData("Truncated", "\"{\\\"type\\\":\\\"decisions\\\",\\\"cycle\\\":2,\\\"deci\\n\"", "first: cycle 3: ")]
    [InlineData("BadGear", "\"{\\\"type\\\":\\\"decisions\\\",\\\"cycle\\\":2,\\\"decisions\\\":[[99,7],[1,7]]}\\n\"", "first: cycle 3: ")]
    [InlineData("NotDecisions", "\"{\\\"type\\\":\\\"hello\\\",\\\"version\\\":1}\\n\"", "first: cycle 3: the host answered something other than decisions")]
    public void One_bad_line_is_one_bad_answer_and_the_host_is_back_in_step(string name, string line, string first)
    {
        string faults = Faults(Run(Strategy(name, line)));
        Assert.StartsWith("0 exceptions, 0 timeouts, 1 bad answers; its fish kept their last decisions; " + first, faults, StringComparison.Ordinal);
    }

    [Attack("faults", "it answers something unusable")]
    [Fact]
    public void An_answer_to_an_earlier_cycle_is_skipped_not_charged()
    {
        // Its own right answer, then an old cycle's: the old line (and the host's own answer after it) are skipped.
        var run = Run(Strategy("OldCycle", "\"{\\\"type\\\":\\\"decisions\\\",\\\"cycle\\\":2,\\\"decisions\\\":[[1,7],[1,7]]}\\n{\\\"type\\\":\\\"decisions\\\",\\\"cycle\\\":1,\\\"decisions\\\":[[1,7],[1,7]]}\\n\""));
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("strategy faults: none\n", run.Stdout, StringComparison.Ordinal);
    }

    [Attack("faults", "a line longer than 65,536 bytes")]
    [Fact]
    public void A_line_over_the_limit_is_a_bad_answer_and_closes_the_connection()
    {
        string faults = Faults(Run(Strategy("Oversize", "new string('x', 70000) + \"\\n\"")));
        Assert.Equal("0 exceptions, 0 timeouts, 1 bad answers, strategy host ended in cycle 3; its fish kept their last decisions until then and stopped after; first: cycle 3: a line is longer than 65536 bytes", faults);
    }

    [Attack("faults", "its host ends")]
    [Fact]
    public void A_line_cut_short_by_the_hosts_end_ends_the_host()
    {
        string faults = Faults(Run(Strategy("CutShort", "\"{\\\"type\\\":\\\"decisions\\\",\\\"cycle\\\":2,\\\"deci\"", "Environment.Exit(3);")));
        Assert.StartsWith("0 exceptions, 0 timeouts, 0 bad answers, strategy host ended in cycle 3; its fish kept their last decisions until then and stopped after; first: cycle 3: strategy host ended: exit code 3", faults, StringComparison.Ordinal);
    }
}
