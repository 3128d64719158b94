namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// What a strategy prints reaches the terminal: without <c>--strategy-log</c> a strategy host's
/// output goes on to the server's standard error as it is written; <c>--strategy-log</c> without
/// <c>--trace</c>, <c>--html</c> or <c>--live</c> prints each cycle's output there with its cycle and team.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class StrategyConsoleTests() : TempFolderTest("urwpg-console-")
{
    private string Printer() => SdkStrategy.Write(Folder, "Printer", "printer", """
        Console.WriteLine($"saw cycle {s.Cycle}");
        for (int i = 0; i < d.Length; i++)
        {
            d[i] = new Decision(5, 7);
        }
        """);

    [Fact]
    public void What_a_hosted_strategy_prints_reaches_the_servers_standard_error_by_default()
    {
        // The real program (its own standard error), with the default isolation: strategy hosts.
        var (code, stdout, stderr) = DocsOutputsTests.RunServer(string.Empty, ["run", "--item", "default", "--cycles", "6", "--strategy", "0=" + Printer(), "--strategy-timeout", "5000"]);
        Assert.True(code == 0, stderr);
        for (int cycle = 0; cycle < 6; cycle++)
        {
            Assert.Contains($"saw cycle {cycle}\n", stderr, StringComparison.Ordinal);
        }

        Assert.DoesNotContain("saw cycle", stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("process")]
    [InlineData("none")]
    public void Strategy_log_alone_prints_each_cycles_output_with_its_cycle_and_team(string isolation)
    {
        var run = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "4", "--strategy", "0=" + Printer(), "--isolation", isolation,
            "--strategy-timeout", "5000", "--strategy-log");
        Assert.True(run.ExitCode == 0, run.Stderr);
        for (int cycle = 1; cycle <= 4; cycle++)
        {
            Assert.Contains($"cycle {cycle}, team 0 (printer [Printer.cs]): saw cycle {cycle - 1}\n", run.Stderr, StringComparison.Ordinal); // decided from the previous cycle's snapshot
        }

        Assert.DoesNotContain("saw cycle", run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void Strategy_log_does_not_go_with_a_batch()
    {
        var run = CliRun.Of(string.Empty, "run", "--batch", "2", "--cycles", "3", "--strategy-log");
        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith("run: --strategy-log shows what the strategies print in one match", run.Stderr, StringComparison.Ordinal);
        Assert.Equal(string.Empty, run.Stdout);
    }
}
