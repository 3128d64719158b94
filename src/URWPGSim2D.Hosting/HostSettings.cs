namespace URWPGSim2D.Hosting;

/// <summary>How user strategies are run: <c>--isolation</c>, <c>--sandbox</c>, <c>--strategy-memory</c>, <c>--strategy-scratch</c>, <c>--strategy-processes</c>.</summary>
/// <param name="Isolation">In a host process or in the server's process.</param>
/// <param name="Sandbox">Whether hosts run in bubblewrap.</param>
/// <param name="MemoryMb">The GC heap hard limit of a host, MiB.</param>
/// <param name="ScratchMb">The size of a sandboxed host's scratch folder and of its /tmp, MiB each.</param>
/// <param name="Processes">The most processes and threads a host's sandbox may hold at once.</param>
public sealed record HostSettings(
    IsolationMode Isolation = IsolationMode.Process,
    SandboxMode Sandbox = SandboxMode.Auto,
    int MemoryMb = HostSettings.DefaultMemoryMb,
    int ScratchMb = HostSettings.DefaultScratchMb,
    int Processes = HostSettings.DefaultProcesses)
{
    /// <summary>Default <c>--strategy-memory</c>: 1 GiB.</summary>
    public const int DefaultMemoryMb = 1024;

    /// <summary>Default <c>--strategy-scratch</c>: 64 MiB.</summary>
    public const int DefaultScratchMb = 64;

    /// <summary>Default <c>--strategy-processes</c>: 256 (a host's runtime has about 20 threads).</summary>
    public const int DefaultProcesses = 256;

    /// <summary>Memory of a host's whole sandbox beyond its heap limit and its RAM-backed folders: the runtime, its code and stacks, MiB.</summary>
    public const int RuntimeMb = 256;

    /// <summary>The default: process isolation, sandbox where possible, 1 GiB.</summary>
    public static HostSettings Default { get; } = new();

    /// <summary>The memory limit of a host's whole sandbox, bytes: heap, runtime, scratch and /tmp.</summary>
    public long SandboxMemoryBytes => ((long)MemoryMb + RuntimeMb + (2L * ScratchMb)) * 1024 * 1024;
}
