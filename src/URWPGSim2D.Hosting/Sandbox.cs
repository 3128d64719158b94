namespace URWPGSim2D.Hosting;

/// <summary>
/// The bubblewrap sandbox of a strategy host on Linux: new user (as nobody), PID, network, IPC, UTS
/// and cgroup namespaces; a root file system that holds only the system's libraries (<c>/usr</c>,
/// read-only), the .NET runtime and the server's program files (read-only), the strategy's own files
/// (read-only), <c>/proc</c> of its own PID namespace, a minimal <c>/dev</c>, and a private <c>/tmp</c>,
/// <c>/dev/shm</c> and scratch folder (its working directory) on size-limited tmpfs, so nothing it
/// writes reaches the machine's disk; an empty environment but for the variables the host needs.
/// Its processes die with the host (the host's bubblewrap is the PID namespace's init) and with the
/// server (<c>--die-with-parent</c>). Whether bubblewrap works here is found out once, by running it.
/// </summary>
internal static class Sandbox
{
    private static readonly Lazy<string?> Problem = new(Probe);

    /// <summary>The bubblewrap program.</summary>
    public const string Bwrap = "bwrap";

    /// <summary>Why the sandbox cannot be set up on this machine, or null when it can.</summary>
    public static string? Unavailable => Problem.Value;

    /// <summary>
    /// The bubblewrap arguments (before the command) for a host that may read <paramref name="readOnly"/>
    /// and write <paramref name="scratch"/> (a tmpfs of <paramref name="scratchBytes"/> there, as /tmp and
    /// /dev/shm), with <paramref name="environment"/> as its whole environment; it may also write the
    /// folders <paramref name="writable"/> (the compiler's output folder), if any.
    /// </summary>
    public static List<string> Arguments(IEnumerable<string> readOnly, string scratch, IReadOnlyDictionary<string, string> environment, long scratchBytes, IEnumerable<string>? writable = null)
    {
        string size = scratchBytes.ToString(System.Globalization.CultureInfo.InvariantCulture);
        var a = new List<string>
        {
            "--unshare-all", "--uid", "65534", "--gid", "65534", "--new-session", "--die-with-parent",
            "--ro-bind", "/usr", "/usr",
            "--proc", "/proc", "--dev", "/dev", "--size", size, "--tmpfs", "/dev/shm", "--size", size, "--tmpfs", "/tmp",
        };
        foreach (string top in new[] { "/bin", "/sbin", "/lib", "/lib64", "/lib32", "/libx32" })
        {
            var info = new DirectoryInfo(top);
            if (info.LinkTarget is { } target)
            {
                a.AddRange(["--symlink", target, top]); // merged /usr: /lib -> usr/lib
            }
            else if (info.Exists)
            {
                a.AddRange(["--ro-bind", top, top]);
            }
        }

        var bound = new HashSet<string>(StringComparer.Ordinal) { "/usr" };
        foreach (string path in readOnly)
        {
            string full = Path.TrimEndingDirectorySeparator(Path.GetFullPath(path));
            if (bound.Add(full) && !full.StartsWith("/usr/", StringComparison.Ordinal))
            {
                a.AddRange(["--ro-bind", full, full]);
            }
        }

        foreach (string path in writable ?? [])
        {
            string full = Path.TrimEndingDirectorySeparator(Path.GetFullPath(path));
            a.AddRange(["--bind", full, full]);
        }

        a.AddRange(["--size", size, "--perms", "0700", "--tmpfs", scratch, "--chdir", scratch, "--clearenv"]);
        foreach (var pair in environment)
        {
            a.AddRange(["--setenv", pair.Key, pair.Value]);
        }

        a.Add("--");
        return a;
    }

    private static string? Probe()
    {
        if (!OperatingSystem.IsLinux())
        {
            return "bubblewrap runs on Linux only";
        }

        var start = new ProcessStartInfo(Bwrap) { RedirectStandardError = true, RedirectStandardOutput = true, UseShellExecute = false };
        foreach (string arg in Arguments([], "/tmp/urwpgsim2d-probe", new Dictionary<string, string>(), 1 << 20))
        {
            start.ArgumentList.Add(arg);
        }

        start.ArgumentList.Add("/usr/bin/true");
        try
        {
            using var probe = Process.Start(start)!;
            string error = probe.StandardError.ReadToEnd();
            if (!probe.WaitForExit(10_000))
            {
                probe.Kill(entireProcessTree: true);
                return "bwrap did not finish a trial run within 10 s";
            }

            return probe.ExitCode == 0 ? null : $"bwrap failed a trial run ({error.Trim().ReplaceLineEndings(" ")})";
        }
        catch (System.ComponentModel.Win32Exception e)
        {
            return $"bwrap cannot be started ({e.Message}; install the bubblewrap package)";
        }
    }
}
