using System.Threading;

namespace URWPGSim2D.Hosting;

/// <summary>Makes each host's control group, and says once per run where none can be made.</summary>
internal static class HostCgroup
{
    private static int _warned;

    /// <summary>A new control group limited by <paramref name="settings"/>, or null (one warning line, the first time) where none can be made.</summary>
    public static SandboxCgroup? Create(HostSettings settings)
    {
        if (!System.OperatingSystem.IsLinux())
        {
            return null;
        }

        var group = SandboxCgroup.Create(settings.SandboxMemoryBytes, settings.Processes, out string? problem);
        if (group is null && Interlocked.Exchange(ref _warned, 1) == 0)
        {
            HostSandbox.Warn?.Invoke($"warning: strategy hosts run without a memory limit of their whole sandbox or a process limit: {problem}");
        }

        return group;
    }
}
