using URWPGSim2D.Server.Tests.Trace;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// <c>--threads P</c> for a single match: the motion world samples each cycle's islands on P threads,
/// and the trace (poses, contacts in order, scores, events) is byte-identical for 1, 2 and 4
/// threads, on crowds large enough to use the threads and on the default match; the CLI prints
/// the same summary whatever P.
/// </summary>
public sealed class MotionWorldThreadsTests
{
    [Theory]
    [InlineData(400, 3UL)]
    [InlineData(1_000, 1UL)]
    public void ACrowdIsTheSameOnOneTwoAndFourThreads(int movers, ulong seed)
    {
        var scenario = CrowdScenario.Create(movers, seed);
        byte[] one = Trace(scenario, 1, 25, out int chunks);
        Assert.Equal(1, chunks);
        Assert.Equal(one, Trace(scenario, 2, 25, out chunks));
        Assert.Equal(2, chunks);
        Assert.Equal(one, Trace(scenario, 4, 25, out chunks));
        Assert.Equal(4, chunks);
    }

    [Fact]
    public void TheDefaultMatchIsTheSameOnTwoThreads()
    {
        var scenario = DefaultScenario.Load();
        Assert.Equal(Trace(scenario, 1, 150, out _), Trace(scenario, 2, 150, out _));
    }

    [Fact]
    public void RunWithThreadsPrintsTheSameMatch()
    {
        // 2,100 fish and balls: above the size below which a match uses one thread whatever --threads says.
        string one = Summary(CliRun.Of(string.Empty, "run", "--crowd", "2100", "--cycles", "3"));
        string two = Summary(CliRun.Of(string.Empty, "run", "--crowd", "2100", "--cycles", "3", "--threads", "2"));
        Assert.Equal(one, two);
        Assert.Contains("contacts:", one, StringComparison.Ordinal);
    }

    // The output but for its first line (wall time).
    private static string Summary(CliRun run)
    {
        Assert.True(run.ExitCode == 0, run.Stderr);
        return run.Stdout[(run.Stdout.IndexOf('\n', StringComparison.Ordinal) + 1)..];
    }

    private static byte[] Trace(ScenarioDefinition scenario, int threads, int cycles, out int chunks)
    {
        var match = MatchBuilder.Build(scenario);
        match.Motion.Threads = threads;
        match.Motion.MinimumMoversForThreads = 64; // below the default, so that these crowds use the threads
        int most = 0;
        byte[] trace = TraceBytes.Of(match, cycles, _ => most = Math.Max(most, match.Motion.Chunks));
        chunks = most;
        return trace;
    }
}
