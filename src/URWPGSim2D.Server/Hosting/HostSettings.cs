namespace URWPGSim2D.Server.Hosting;

/// <summary>How user strategies are run: <c>--isolation</c>, <c>--sandbox</c>, <c>--strategy-memory</c>.</summary>
/// <param name="Isolation">In a host process or in the server's process.</param>
/// <param name="Sandbox">Whether hosts run in bubblewrap.</param>
/// <param name="MemoryMb">The GC heap hard limit of a host, MiB.</param>
internal sealed record HostSettings(IsolationMode Isolation = IsolationMode.Process, SandboxMode Sandbox = SandboxMode.Auto, int MemoryMb = HostSettings.DefaultMemoryMb)
{
    /// <summary>Default <c>--strategy-memory</c>: 1 GiB.</summary>
    public const int DefaultMemoryMb = 1024;

    /// <summary>The default: process isolation, sandbox where possible, 1 GiB.</summary>
    public static HostSettings Default { get; } = new();
}
