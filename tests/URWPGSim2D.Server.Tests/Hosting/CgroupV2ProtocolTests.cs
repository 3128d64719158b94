namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// The cgroup v2 side of a sandbox's control group, against a folder that stands for a cgroup2
/// hierarchy with the memory and pids controllers (this machine's cgroup2 hierarchy has its
/// controllers bound to v1, so it gives none): the limits written, the wrapper's join, the CPU time,
/// the CPU wait and the out-of-memory kill read, the kill through <c>cgroup.kill</c> and the end
/// when <c>pids.current</c> is 0.
/// </summary>
public sealed class CgroupV2ProtocolTests : IDisposable
{
    private readonly string _root = Directory.CreateTempSubdirectory("urwpg-cgroup2-").FullName;

    public void Dispose() => Directory.Delete(_root, recursive: true);

    [Fact]
    public void A_v2_group_is_limited_joined_measured_and_killed_through_its_files()
    {
        string group = Path.Combine(_root, "g");
        Directory.CreateDirectory(group);
        File.WriteAllText(Path.Combine(group, "cpu.stat"), "usage_usec 1234567\nuser_usec 1000000\nsystem_usec 234567\n");
        File.WriteAllText(Path.Combine(group, "cpu.pressure"), "some avg10=0.00 avg60=0.00 avg300=0.00 total=250000\nfull avg10=0.00 avg60=0.00 avg300=0.00 total=0\n");
        File.WriteAllText(Path.Combine(group, "memory.events"), "low 0\nhigh 0\nmax 3\noom 1\noom_kill 1\n");
        File.WriteAllText(Path.Combine(group, "cgroup.kill"), "");
        File.WriteAllText(Path.Combine(group, "cgroup.procs"), "");
        File.WriteAllText(Path.Combine(group, "pids.current"), "0\n");
        var layout = new SandboxCgroup.Layout(true, [_root]) { CpuFolder = 0, PressureFolder = 0, UnifiedFolder = 0 };

        var cgroup = SandboxCgroup.Create(layout, "g", 352L << 20, 100, out string? problem);
        Assert.True(cgroup is not null, problem);
        Assert.Equal("369098752", File.ReadAllText(Path.Combine(group, "memory.max")));
        Assert.Equal("0", File.ReadAllText(Path.Combine(group, "memory.swap.max")));
        Assert.Equal("100", File.ReadAllText(Path.Combine(group, "pids.max")));
        var wrapper = cgroup.Wrapper().ToList();
        Assert.Equal(["/bin/sh", "-c"], wrapper.Take(2));
        Assert.Equal([Path.Combine(group, "cgroup.procs"), "--"], wrapper.TakeLast(2));
        Assert.Equal(TimeSpan.FromMicroseconds(1234567), cgroup.CpuTime());
        Assert.Equal(TimeSpan.FromMicroseconds(250000), cgroup.WaitingTime());
        Assert.True(cgroup.OutOfMemory());
        Assert.Equal(0, cgroup.Tasks());
        Assert.True(cgroup.KillAll());
        Assert.Equal("1", File.ReadAllText(Path.Combine(group, "cgroup.kill")));

        File.WriteAllText(Path.Combine(group, "memory.events"), "low 0\nhigh 0\nmax 0\noom 0\noom_kill 0\n");
        Assert.False(cgroup.OutOfMemory());
        File.WriteAllText(Path.Combine(group, "pids.current"), "3\n");
        Assert.Equal(3, cgroup.Tasks());
    }

    [Fact]
    public void A_v2_hierarchy_without_its_files_gives_no_group_and_says_why()
    {
        var layout = new SandboxCgroup.Layout(true, [Path.Combine(_root, "absent", "deeper")]) { CpuFolder = 0, UnifiedFolder = 0 };
        File.WriteAllText(Path.Combine(_root, "absent"), "a file, not a folder");
        Assert.Null(SandboxCgroup.Create(layout, "g", 64L << 20, 64, out string? problem));
        Assert.StartsWith("cannot make a cgroup: ", problem, StringComparison.Ordinal);
    }

    [Fact]
    public void Groups_left_by_servers_that_no_longer_run_are_removed_and_the_others_kept()
    {
        int own = Environment.ProcessId;
        string[] stale = ["urwpgsim2d-400001-1", "urwpgsim2d-400001-2", "urwpgsim2d-400002-probe"];
        string[] kept = [$"urwpgsim2d-{own}-7", "urwpgsim2d-400003-1", "urwpgsim2d-x-1", "urwpgsim2d-", "another-400001-1"];
        foreach (string name in stale.Concat(kept))
        {
            Directory.CreateDirectory(Path.Combine(_root, name));
        }

        var layout = new SandboxCgroup.Layout(true, [_root]) { CpuFolder = 0, UnifiedFolder = 0 };
        var asked = new System.Collections.Generic.List<int>();

        int removed = SandboxCgroup.SweepStale(layout, pid => { asked.Add(pid); return pid == 400003; });

        Assert.Equal(3, removed);
        Assert.Equal(kept.Order(StringComparer.Ordinal), Directory.GetDirectories(_root).Select(Path.GetFileName).Order(StringComparer.Ordinal));
        Assert.DoesNotContain(own, asked); // this server's own groups are never in question
    }
}
