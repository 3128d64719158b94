using System.Runtime.InteropServices;

namespace URWPGSim2D.Hosting;

/// <summary>
/// The control group of one strategy host (Linux): every process the host starts is in it, so the
/// whole sandbox is limited as one (its memory, heap and native and its RAM-backed files; the number
/// of its processes and threads) and ended as one, however its processes hide (<c>setsid</c>, double
/// forks, a fork bomb). Works with cgroups v1 (the <c>memory</c> and <c>pids</c> hierarchies) and v2
/// (one hierarchy with both controllers), through their files. The host is put into the group by a
/// <c>/bin/sh</c> wrapper before it starts (<see cref="Wrapper"/>), so not even its first child is
/// outside. Where no such group can be made (no cgroups, no permission, not Linux) <see cref="Unavailable"/>
/// says why and hosts run without these limits.
/// </summary>
internal sealed partial class SandboxCgroup : IDisposable
{
    private static readonly Lazy<Layout?> Found = new(Find);
    private static readonly Lazy<string?> Problem = new(Probe);
    private static readonly Lazy<int> Swept = new(() => Found.Value is { } layout ? SweepStale(layout, LeftBehind.Running) : 0);
    private static int _next;
    private readonly string[] _folders;
    private readonly Layout _layout;
    private readonly Microsoft.Win32.SafeHandles.SafeFileHandle? _cpuUsage;
    private readonly Microsoft.Win32.SafeHandles.SafeFileHandle? _cpuPressure;
    private readonly Microsoft.Win32.SafeHandles.SafeFileHandle? _memoryPeak;
    private readonly string? _killFile;
    private readonly HashSet<int> _seen = [];
    private int _disposed;

    private SandboxCgroup(Layout layout, string[] folders, long memoryBytes)
    {
        _layout = layout;
        _folders = folders;
        MemoryBytes = memoryBytes;
        if (layout.CpuUsage is { } usage)
        {
            try
            {
                _cpuUsage = File.OpenHandle(Path.Combine(folders[usage.Folder], usage.File));
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                _cpuUsage = null; // no CPU time of the whole sandbox: the wall time still counts
            }
        }

        try
        {
            // v1: the group's high-water mark; v2: memory.peak (Linux 5.19 and later).
            _memoryPeak = File.OpenHandle(Path.Combine(folders[0], layout.V2 ? "memory.peak" : "memory.max_usage_in_bytes"));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            _memoryPeak = null; // no high-water mark: the memory is not measured
        }

        if (layout.UnifiedFolder is { } unified && File.Exists(Path.Combine(folders[unified], "cgroup.kill")))
        {
            _killFile = Path.Combine(folders[unified], "cgroup.kill");
        }

        if (layout.PressureFolder is { } pressure)
        {
            try
            {
                _cpuPressure = File.OpenHandle(Path.Combine(folders[pressure], "cpu.pressure"));
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                _cpuPressure = null; // no pressure stall information: a busy machine's waits count as the call's wall time
            }
        }
    }

    /// <summary>This machine's hierarchy for the groups of this process's hosts, or null where there is none.</summary>
    internal static Layout? Machine => Found.Value;

    /// <summary>Why no group can be made here, or null when it can.</summary>
    public static string? Unavailable => Problem.Value;

    /// <summary>The group's memory limit, bytes.</summary>
    public long MemoryBytes { get; }

    /// <summary>
    /// A new group limited to <paramref name="memoryBytes"/> of memory and <paramref name="tasks"/>
    /// processes and threads, or null (and why) when none can be made.
    /// </summary>
    public static SandboxCgroup? Create(long memoryBytes, int tasks, out string? problem)
    {
        problem = Unavailable;
        if (problem is not null || Found.Value is not { } layout)
        {
            problem ??= "no cgroup hierarchy with the memory and pids controllers";
            return null;
        }

        _ = Swept.Value;
        string name = LeftBehind.Name(Interlocked.Increment(ref _next).ToString(CultureInfo.InvariantCulture));
        return Create(layout, name, memoryBytes, tasks, out problem);
    }

    /// <summary>
    /// Ends and removes the groups that servers which no longer run left behind (a server killed
    /// before it could remove its hosts' groups): every group named <c>urwpgsim2d-PID-…</c> in the
    /// parents of <paramref name="layout"/> whose PID is not a running process (and not this one).
    /// Whatever still runs in such a group (a daemon a strategy started, without bubblewrap) is
    /// killed first. Groups of running servers are left alone.
    /// </summary>
    /// <param name="layout">The hierarchy.</param>
    /// <param name="running">Whether a process with this id runs now.</param>
    /// <returns>How many groups were removed.</returns>
    internal static int SweepStale(Layout layout, Func<int, bool> running)
    {
        var stale = new SortedSet<string>(StringComparer.Ordinal);
        foreach (string parent in layout.Parents)
        {
            try
            {
                foreach (string folder in Directory.EnumerateDirectories(parent, LeftBehind.Prefix + "*"))
                {
                    string name = Path.GetFileName(folder);
                    if (LeftBehind.ByEndedServer(name, running))
                    {
                        stale.Add(name);
                    }
                }
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // a parent this process may not list: nothing to sweep there
            }
        }

        int removed = 0;
        foreach (string name in stale)
        {
            string[] folders = Array.ConvertAll(layout.Parents, parent => Path.Combine(parent, name));
            using (var group = new SandboxCgroup(layout, folders, 0))
            {
                // Dispose ends every process of the group and removes its folders.
            }

            removed += Array.TrueForAll(folders, folder => !Directory.Exists(folder)) ? 1 : 0;
        }

        return removed;
    }

    /// <summary>
    /// A new group <paramref name="name"/> in each parent of <paramref name="layout"/> (a hierarchy
    /// chosen by the caller: v1 or v2, the machine's or a folder that stands for one), limited as
    /// <see cref="Create(long, int, out string?)"/> limits it, or null (and why).
    /// </summary>
    internal static SandboxCgroup? Create(Layout layout, string name, long memoryBytes, int tasks, out string? problem)
    {
        problem = null;
        var made = new List<string>();
        try
        {
            foreach (string parent in layout.Parents)
            {
                string folder = Path.Combine(parent, name);
                Directory.CreateDirectory(folder);
                made.Add(folder);
            }

            var group = new SandboxCgroup(layout, [.. made], memoryBytes);
            string memory = memoryBytes.ToString(CultureInfo.InvariantCulture);
            string count = tasks.ToString(CultureInfo.InvariantCulture);
            if (layout.V2)
            {
                File.WriteAllText(Path.Combine(made[0], "memory.max"), memory);
                TryWrite(Path.Combine(made[0], "memory.swap.max"), "0");
                File.WriteAllText(Path.Combine(made[0], "pids.max"), count);
            }
            else
            {
                File.WriteAllText(Path.Combine(made[0], "memory.limit_in_bytes"), memory);
                TryWrite(Path.Combine(made[0], "memory.memsw.limit_in_bytes"), memory); // no swap beyond it
                File.WriteAllText(Path.Combine(made[1], "pids.max"), count);
            }

            return group;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            foreach (string folder in made)
            {
                TryRemove(folder);
            }

            problem = "cannot make a cgroup: " + e.Message;
            return null;
        }
    }

    /// <summary>
    /// The command that joins this group and then runs the rest of the command line in it (its
    /// process, and everything that process starts, is in the group from its first instruction).
    /// </summary>
    public IEnumerable<string> Wrapper()
    {
        yield return "/bin/sh";
        yield return "-c";
        yield return "for f in \"$@\"; do [ \"$f\" = -- ] && break; echo $$ > \"$f\" || exit 125; shift; done; shift; exec \"$@\"";
        yield return "urwpgsim2d-host";
        foreach (string folder in _folders)
        {
            yield return Path.Combine(folder, "cgroup.procs");
        }

        yield return "--";
    }

    /// <summary>
    /// The CPU time all processes of the group have used so far (every thread, every child, however
    /// it hides), or null where the group has no CPU accounting. One read of an open file; no allocation.
    /// </summary>
    public TimeSpan? CpuTime()
    {
        // v1: "<nanoseconds>\n"; v2: "usage_usec <microseconds>\n…".
        Span<byte> text = stackalloc byte[64];
        var line = FirstLine(_cpuUsage, text);
        if (_layout.V2)
        {
            int space = line.IndexOf((byte)' ');
            line = space >= 0 ? line[(space + 1)..] : [];
        }

        return Number(line, out long value) ? TimeSpan.FromTicks(_layout.V2 ? value * 10 : value / 100) : null;
    }

    /// <summary>
    /// The most memory the group's processes have held at once so far (heap, runtime and mapped files,
    /// RAM-backed files too: what its memory limit counts), bytes, or null where the kernel does not
    /// give it. One read of an open file; no allocation.
    /// </summary>
    public long? PeakMemoryBytes()
    {
        Span<byte> text = stackalloc byte[32];
        return Number(FirstLine(_memoryPeak, text), out long value) ? value : null;
    }

    /// <summary>
    /// How long, so far, some process of the group was ready to run but waited for a CPU (the
    /// kernel's pressure stall information, <c>cpu.pressure</c>'s <c>some total</c>): time a busy
    /// machine took from the sandbox, not time the sandbox spent; null where the kernel does not
    /// give it. One read of an open file; no allocation.
    /// </summary>
    public TimeSpan? WaitingTime()
    {
        // "some avg10=0.00 avg60=0.00 avg300=0.00 total=<microseconds>\n…"
        Span<byte> text = stackalloc byte[128];
        var line = FirstLine(_cpuPressure, text);
        int at = line.IndexOf("total="u8);
        return at >= 0 && Number(line[(at + 6)..], out long micro) ? TimeSpan.FromTicks(micro * 10) : null;
    }

    // The first line of a group file read whole into the buffer from its start; empty when there is no such file or it cannot be read.
    private static ReadOnlySpan<byte> FirstLine(Microsoft.Win32.SafeHandles.SafeFileHandle? file, Span<byte> buffer)
    {
        if (file is null)
        {
            return [];
        }

        int n;
        try
        {
            n = RandomAccess.Read(file, buffer, 0);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ObjectDisposedException)
        {
            return [];
        }

        var line = buffer[..n];
        int nl = line.IndexOf((byte)'\n');
        return nl >= 0 ? line[..nl] : line;
    }

    // A whole decimal number, and nothing else.
    private static bool Number(ReadOnlySpan<byte> text, out long value) =>
        System.Buffers.Text.Utf8Parser.TryParse(text, out value, out int used) && used == text.Length && used > 0;

    /// <summary>Whether the kernel killed a process of the group for want of memory.</summary>
    public bool OutOfMemory()
    {
        string file = Path.Combine(_folders[0], _layout.V2 ? "memory.events" : "memory.oom_control");
        try
        {
            foreach (string line in File.ReadLines(file))
            {
                if (line.StartsWith("oom_kill ", StringComparison.Ordinal) && long.TryParse(line.AsSpan(9), NumberStyles.None, CultureInfo.InvariantCulture, out long kills) && kills > 0)
                {
                    return true;
                }
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // gone or unreadable: not known to be out of memory
        }

        return false;
    }

    /// <summary>The processes of the group now.</summary>
    public List<int> Processes()
    {
        var pids = new List<int>();
        foreach (string folder in _folders)
        {
            try
            {
                foreach (string line in File.ReadLines(Path.Combine(folder, "cgroup.procs")))
                {
                    if (int.TryParse(line, NumberStyles.None, CultureInfo.InvariantCulture, out int pid) && !pids.Contains(pid))
                    {
                        pids.Add(pid);
                    }
                }
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // removed already
            }
        }

        return pids;
    }

    /// <summary>
    /// Ends every process of the group (a fork bomb included) and returns when the kernel has reaped
    /// them all (or all that are left are zombies of it, <see cref="Remember"/>), so that nothing of
    /// the sandbox runs any more: true then; false (and one warning line) when some still run after
    /// <see cref="ReapLimit"/>.
    /// </summary>
    /// <remarks>
    /// A process leaves <c>cgroup.procs</c> as it starts to exit, before it has finished; and when the
    /// init of the sandbox's PID namespace dies, the kernel ends the namespace's other processes and
    /// holds the init back (out of the group's list, still running) until they are all reaped. An
    /// empty <c>cgroup.procs</c> therefore does not mean an ended sandbox; the group's
    /// <c>pids.current</c>, which counts every task of the group until it is reaped, reaching 0 does.
    /// Where a v2 group has <c>cgroup.kill</c> (Linux 5.14 and later; also the unified group of a
    /// hybrid machine) the kernel kills the whole group at once, processes forking meanwhile included;
    /// elsewhere whatever is listed is killed until nothing is (the pids limit bounds the forks).
    /// </remarks>
    public bool KillAll()
    {
        lock (_seen)
        {
            return KillAllOnce();
        }
    }

    private bool KillAllOnce()
    {
        bool atOnce = _killFile is not null && TryWrite(_killFile, "1");
        long until = Environment.TickCount64 + (long)ReapLimit.TotalMilliseconds;
        for (int round = 0; ; round++)
        {
            foreach (int pid in Processes())
            {
                _seen.Add(pid);
                if (!atOnce || round > 0)
                {
                    _ = Kill(pid, 9); // one forked meanwhile is listed next round
                }
            }

            long left = Tasks();
            if (left == 0 || left == Zombies())
            {
                return true;
            }

            if (Environment.TickCount64 > until)
            {
                HostSandbox.Warn?.Invoke(string.Create(CultureInfo.InvariantCulture, $"warning: {left} processes of a strategy sandbox were not reaped within {ReapLimit.TotalSeconds:0} s"));
                return false;
            }

            Thread.Sleep(round < 20 ? 1 : 5);
        }
    }

    /// <summary>
    /// Notes the processes of the group now (the sandbox's PID namespace's init among them, once
    /// the sandbox is up), so that <see cref="KillAll"/> knows them as its own when they are zombies
    /// left to a parent outside the group: an ended process no longer listed in the group, which
    /// only the machine's init can reap, and which may never be (a container's first process).
    /// </summary>
    public void Remember()
    {
        lock (_seen)
        {
            foreach (int pid in Processes())
            {
                _seen.Add(pid);
            }
        }
    }

    /// <summary>How many of the processes seen in the group (<see cref="Remember"/>, <see cref="KillAll"/>) are zombies now: ended, not yet reaped.</summary>
    public int Zombies()
    {
        int zombies = 0;
        lock (_seen)
        {
            foreach (int pid in _seen)
            {
                try
                {
                    string stat = File.ReadAllText("/proc/" + pid.ToString(CultureInfo.InvariantCulture) + "/stat");
                    int after = stat.LastIndexOf(')') + 2;
                    zombies += after < stat.Length && stat[after] == 'Z' ? 1 : 0;
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    // reaped
                }
            }
        }

        return zombies;
    }

    /// <summary>How long <see cref="KillAll"/> waits for the kernel to reap the group's processes before it gives up with a warning.</summary>
    public static readonly TimeSpan ReapLimit = TimeSpan.FromSeconds(10);

    /// <summary>
    /// How many tasks (processes and threads) of the group the kernel has not reaped yet: its
    /// <c>pids.current</c>, running, exiting and zombie ones alike; where that file cannot be read,
    /// the processes <c>cgroup.procs</c> lists (0 once the group is removed).
    /// </summary>
    public long Tasks()
    {
        Span<byte> text = stackalloc byte[32];
        string folder = _folders[_layout.PidsFolder];
        try
        {
            using var handle = File.OpenHandle(Path.Combine(folder, "pids.current"));
            var line = FirstLine(handle, text);
            if (Number(line, out long count))
            {
                return count;
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // not there: count the listed processes
        }

        return Processes().Count;
    }

    /// <summary>Ends every process of the group and removes the group.</summary>
    public void Dispose()
    {
        if (Interlocked.Exchange(ref _disposed, 1) != 0)
        {
            return;
        }

        _ = KillAll();
        _cpuUsage?.Dispose();
        _cpuPressure?.Dispose();
        _memoryPeak?.Dispose();
        foreach (string folder in _folders)
        {
            // A killed process leaves the group when the kernel has finished with it: a few tries.
            for (int attempt = 0; attempt < 100 && !TryRemove(folder); attempt++)
            {
                Thread.Sleep(10);
            }
        }
    }

    private static bool TryWrite(string file, string text)
    {
        try
        {
            File.WriteAllText(file, text);
            return true;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    private static bool TryRemove(string folder)
    {
        try
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder); // a cgroup's files go with it: not recursive
            }

            return true;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    private static string? Probe()
    {
        if (!OperatingSystem.IsLinux())
        {
            return "cgroups are Linux only";
        }

        if (Found.Value is null)
        {
            return "no cgroup hierarchy with the memory and pids controllers";
        }

        // Make (and remove) one group: the permission to do so is the question.
        string name = LeftBehind.Name("probe");
        foreach (string parent in Found.Value.Parents)
        {
            string folder = Path.Combine(parent, name);
            try
            {
                Directory.CreateDirectory(folder);
                bool limits = File.Exists(Path.Combine(folder, "cgroup.procs")) && (File.Exists(Path.Combine(folder, "memory.max")) || File.Exists(Path.Combine(folder, "memory.limit_in_bytes")) || File.Exists(Path.Combine(folder, "pids.max")) || File.Exists(Path.Combine(folder, "cpuacct.usage")) || File.Exists(Path.Combine(folder, "cpu.pressure")));
                TryRemove(folder);
                if (!limits)
                {
                    return $"the cgroup {parent} gives its children no memory or pids limits";
                }
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                return $"cannot make a cgroup in {parent} ({e.Message})";
            }
        }

        return null;
    }

    // Where this process's groups are: from /proc/self/mounts and /proc/self/cgroup.
    private static Layout? Find()
    {
        if (!OperatingSystem.IsLinux())
        {
            return null;
        }

        try
        {
            var own = new Dictionary<string, string>(StringComparer.Ordinal); // controller (or "" for v2) -> own path
            foreach (string line in File.ReadLines("/proc/self/cgroup"))
            {
                string[] parts = line.Split(':', 3);
                if (parts.Length == 3)
                {
                    foreach (string controller in parts[1].Split(','))
                    {
                        own[controller] = parts[2];
                    }
                }
            }

            string? memoryMount = null, pidsMount = null, cpuMount = null, unified = null;
            foreach (string line in File.ReadLines("/proc/self/mounts"))
            {
                string[] fields = line.Split(' ');
                if (fields.Length < 4)
                {
                    continue;
                }

                if (fields[2] == "cgroup2")
                {
                    unified ??= fields[1];
                }
                else if (fields[2] == "cgroup")
                {
                    string[] options = fields[3].Split(',');
                    if (Array.IndexOf(options, "memory") >= 0)
                    {
                        memoryMount ??= fields[1];
                    }

                    if (Array.IndexOf(options, "pids") >= 0)
                    {
                        pidsMount ??= fields[1];
                    }

                    if (Array.IndexOf(options, "cpuacct") >= 0)
                    {
                        cpuMount ??= fields[1];
                    }
                }
            }

            if (memoryMount is not null && pidsMount is not null && own.TryGetValue("memory", out string? memoryPath) && own.TryGetValue("pids", out string? pidsPath))
            {
                // The cpuacct group, where there is one, measures the CPU time of the whole sandbox; a
                // group in the unified hierarchy beside the v1 ones (hybrid mode), where the kernel
                // gives pressure stall information there, measures how long it waited for a CPU.
                var parents = new List<string> { Under(memoryMount, memoryPath), Under(pidsMount, pidsPath) };
                int? cpu = null, pressure = null;
                if (cpuMount is not null && own.TryGetValue("cpuacct", out string? cpuPath))
                {
                    cpu = parents.Count;
                    parents.Add(Under(cpuMount, cpuPath));
                }

                if (unified is not null && own.TryGetValue(string.Empty, out string? unifiedPath) && File.Exists(Path.Combine(Under(unified, unifiedPath), "cpu.pressure")))
                {
                    pressure = parents.Count;
                    parents.Add(Under(unified, unifiedPath));
                }

                return new Layout(false, [.. parents]) { CpuFolder = cpu, PressureFolder = pressure, UnifiedFolder = pressure };
            }

            if (unified is not null && own.TryGetValue(string.Empty, out string? path))
            {
                string controllers = File.ReadAllText(Path.Combine(unified, "cgroup.controllers"));
                if (!controllers.Contains("memory", StringComparison.Ordinal) || !controllers.Contains("pids", StringComparison.Ordinal))
                {
                    return null;
                }

                // v2 allows no processes in a group whose children have controllers: a group of its
                // own next to this process's, enabled in the parent; the root is exempt.
                string parent = Under(unified, path == "/" ? "/" : Path.GetDirectoryName(path) ?? "/");
                TryWrite(Path.Combine(parent, "cgroup.subtree_control"), "+memory +pids");
                string[] enabled = File.ReadAllText(Path.Combine(parent, "cgroup.subtree_control")).Split(' ', StringSplitOptions.TrimEntries);
                return Array.IndexOf(enabled, "memory") >= 0 && Array.IndexOf(enabled, "pids") >= 0
                    ? new Layout(true, [parent]) { CpuFolder = 0, PressureFolder = File.Exists(Path.Combine(parent, "cpu.pressure")) ? 0 : null, UnifiedFolder = 0 }
                    : null;
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // no cgroups here
        }

        return null;
    }

    private static string Under(string mount, string path) => Path.TrimEndingDirectorySeparator(mount + (path == "/" ? string.Empty : path));

    [LibraryImport("libc", EntryPoint = "kill", SetLastError = true)]
    private static partial int Kill(int pid, int signal);

    /// <summary>v1: the memory group's parent, the pids group's parent and, where there are, the cpuacct group's and a unified group's parents; v2: the one parent.</summary>
    internal sealed record Layout(bool V2, string[] Parents)
    {
        /// <summary>The index into <see cref="Parents"/> of the group that counts the CPU time, or null.</summary>
        public int? CpuFolder { get; init; }

        /// <summary>The index into <see cref="Parents"/> of the group whose <c>cpu.pressure</c> says how long it waited for a CPU, or null.</summary>
        public int? PressureFolder { get; init; }

        /// <summary>The index into <see cref="Parents"/> of the group in a v2 hierarchy (where the kernel gives <c>cgroup.kill</c>), or null.</summary>
        public int? UnifiedFolder { get; init; }

        /// <summary>The index into <see cref="Parents"/> of the group whose <c>pids.current</c> counts the group's tasks.</summary>
        public int PidsFolder => V2 ? 0 : 1;

        /// <summary>The group folder (by index into <see cref="Parents"/>) and file that count the group's CPU time, or null.</summary>
        public (int Folder, string File)? CpuUsage => CpuFolder is { } f ? (f, V2 ? "cpu.stat" : "cpuacct.usage") : null;
    }
}
