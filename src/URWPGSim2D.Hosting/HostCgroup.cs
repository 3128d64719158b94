namespace URWPGSim2D.Hosting;

/// <summary>Makes each host's control group, and says once per run where none can be made.</summary>
internal static class HostCgroup
{
    private static readonly OneWarning NoGroup = new();

    /// <summary>Makes a control group limited to <paramref name="memoryBytes"/> and <paramref name="tasks"/>, or gives null and why.</summary>
    internal delegate SandboxCgroup? Maker(long memoryBytes, int tasks, out string? problem);

    /// <summary>A new control group limited by <paramref name="settings"/>, or null (one warning line, the first time) where none can be made.</summary>
    public static SandboxCgroup? Create(HostSettings settings) =>
        System.OperatingSystem.IsLinux() ? Create(settings, SandboxCgroup.Create, NoGroup) : null;

    /// <summary><see cref="Create(HostSettings)"/> with the group made by <paramref name="make"/> and the warning said through <paramref name="warning"/>.</summary>
    internal static SandboxCgroup? Create(HostSettings settings, Maker make, OneWarning warning)
    {
        var group = make(settings.SandboxMemoryBytes, settings.Processes, out string? problem);
        if (group is null)
        {
            warning.Say($"warning: strategy hosts run without a memory limit of their whole sandbox or a process limit: {problem}");
        }

        return group;
    }
}
