namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Where the machine has no sandbox or no control groups, a run says so in one line however many
/// hosts it starts (from however many threads), keeps playing without them, and refuses only under
/// <c>--sandbox required</c>; and the CPU-time limit every sandboxed child gets stops a spinner with
/// the signal that reads as "took too long", not with SIGKILL.
/// </summary>
public sealed class SandboxWarningTests
{
    [Fact]
    public void Without_control_groups_every_host_runs_without_one_and_the_run_warns_once()
    {
        var lines = new List<string>();
        var warning = new OneWarning(line => { lock (lines) { lines.Add(line); } });
        int asked = 0;
        HostCgroup.Maker none = (long memory, int tasks, out string? problem) =>
        {
            System.Threading.Interlocked.Increment(ref asked);
            Assert.Equal(HostSettings.Default.SandboxMemoryBytes, memory);
            Assert.Equal(HostSettings.Default.Processes, tasks);
            problem = "no cgroup hierarchy with the memory and pids controllers";
            return null;
        };

        Parallel.For(0, 16, _ => Assert.Null(HostCgroup.Create(HostSettings.Default, none, warning)));

        Assert.Equal(16, asked);
        Assert.Equal(["warning: strategy hosts run without a memory limit of their whole sandbox or a process limit: no cgroup hierarchy with the memory and pids controllers"], lines);
    }

    [Fact]
    public void Without_a_sandbox_auto_plays_unsandboxed_after_one_warning_required_refuses_and_off_says_nothing()
    {
        var lines = new List<string>();
        var warning = new OneWarning(lines.Add);
        const string Problem = "bubblewrap (bwrap) is not installed";

        Assert.False(HostSandbox.Use(SandboxMode.Off, null, warning));
        Assert.True(HostSandbox.Use(SandboxMode.Auto, null, warning));
        Assert.True(HostSandbox.Use(SandboxMode.Required, null, warning));
        Assert.Empty(lines);

        for (int i = 0; i < 3; i++)
        {
            Assert.False(HostSandbox.Use(SandboxMode.Auto, Problem, warning));
        }

        var refused = Assert.Throws<StrategyLoadException>(() => HostSandbox.Use(SandboxMode.Required, Problem, warning));
        Assert.Equal("--sandbox required: the strategy sandbox cannot be set up here: " + Problem, refused.Message);
        Assert.Equal(["warning: strategies run in plain child processes without a sandbox: " + Problem], lines);
    }

    [Fact]
    public void The_cpu_limit_of_a_sandboxed_child_stops_a_spinner_with_sigxcpu_not_sigkill()
    {
        if (!File.Exists("/usr/bin/prlimit"))
        {
            Assert.Fail("prlimit (util-linux) is missing: the CPU limit of strategy hosts cannot be checked");
        }

        var limits = SandboxCommand.Limits(1, 0);
        Assert.Equal(["/usr/bin/prlimit", "--cpu=1:2", "--core=0", "--"], limits);
        var start = new ProcessStartInfo(limits[0]) { UseShellExecute = false };
        foreach (string arg in limits[1..])
        {
            start.ArgumentList.Add(arg);
        }

        start.ArgumentList.Add("/bin/sh");
        start.ArgumentList.Add("-c");
        start.ArgumentList.Add("while :; do :; done");
        using var spinner = Process.Start(start)!;
        spinner.WaitForExit();
        Assert.Equal(128 + 24, spinner.ExitCode); // SIGXCPU at the soft limit; SIGKILL (137) would read as a crash
    }
}
