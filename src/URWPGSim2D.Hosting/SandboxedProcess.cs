namespace URWPGSim2D.Hosting;

/// <summary>Ending a child process the sandbox started (a strategy host or the compiler).</summary>
internal static class SandboxedProcess
{
    /// <summary>
    /// Ends <paramref name="process"/> and everything it started: with a control group, every
    /// process of the group at once (bubblewrap included), waiting until they have ended (the PID
    /// namespace's init ends last); without one, the process tree. A process already gone is no error.
    /// </summary>
    public static void Kill(Process process, SandboxCgroup? cgroup)
    {
        if (cgroup is not null)
        {
            _ = cgroup.KillAll();
            return;
        }

        try
        {
            process.Kill(entireProcessTree: true);
        }
        catch (Exception e) when (e is InvalidOperationException or System.ComponentModel.Win32Exception or NotSupportedException)
        {
            // already gone
        }
    }
}
