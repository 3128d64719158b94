namespace URWPGSim2D.Hosting;

/// <summary>
/// The one way a child of a strategy's sandbox (a strategy host or the compiler) is started: joined to
/// its control group before anything else runs (<see cref="SandboxCgroup.Wrapper"/>), inside
/// bubblewrap when sandboxed, under <c>prlimit</c> on Linux (a CPU-time limit, no core dumps and,
/// where asked, an address-space limit), with an empty environment but for what it is given, in its
/// scratch folder.
/// </summary>
internal static class SandboxCommand
{
    private const string Prlimit = "/usr/bin/prlimit";

    /// <summary>The start of <paramref name="program"/> in its sandbox.</summary>
    /// <param name="cgroup">The sandbox's control group, or null where there is none.</param>
    /// <param name="bubblewrap">bubblewrap's arguments (<see cref="Sandbox.Arguments"/>), or null to run unsandboxed.</param>
    /// <param name="cpuSeconds">The CPU time the whole child may use, s: the soft limit (SIGXCPU); the hard one, a second later, is a backstop (with both equal the kernel sends SIGKILL at once, which reads as a crash).</param>
    /// <param name="addressSpaceBytes">The child's address-space limit, bytes; 0 for none.</param>
    /// <param name="program">The program and its arguments.</param>
    /// <param name="scratch">The working directory.</param>
    /// <param name="environment">The child's whole environment.</param>
    public static ProcessStartInfo Create(SandboxCgroup? cgroup, IReadOnlyList<string>? bubblewrap, int cpuSeconds, long addressSpaceBytes, IEnumerable<string> program, string scratch, IReadOnlyDictionary<string, string> environment)
    {
        var command = new List<string>();
        if (cgroup is not null)
        {
            command.AddRange(cgroup.Wrapper());
        }

        if (bubblewrap is not null)
        {
            command.Add(Sandbox.Bwrap);
            command.AddRange(bubblewrap);
        }

        if (OperatingSystem.IsLinux() && File.Exists(Prlimit))
        {
            command.AddRange(Limits(cpuSeconds, addressSpaceBytes));
        }

        command.AddRange(program);
        var start = new ProcessStartInfo(command[0])
        {
            UseShellExecute = false,
            RedirectStandardInput = true,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            WorkingDirectory = scratch,
        };
        for (int i = 1; i < command.Count; i++)
        {
            start.ArgumentList.Add(command[i]);
        }

        start.Environment.Clear();
        foreach (var pair in environment)
        {
            start.Environment[pair.Key] = pair.Value;
        }

        return start;
    }

    /// <summary><c>prlimit</c> and its options up to <c>--</c>.</summary>
    internal static List<string> Limits(int cpuSeconds, long addressSpaceBytes)
    {
        var limits = new List<string> { Prlimit, string.Create(CultureInfo.InvariantCulture, $"--cpu={cpuSeconds}:{cpuSeconds + 1L}"), "--core=0" };
        if (addressSpaceBytes > 0)
        {
            limits.Add(string.Create(CultureInfo.InvariantCulture, $"--as={addressSpaceBytes}"));
        }

        limits.Add("--");
        return limits;
    }
}
