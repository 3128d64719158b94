namespace URWPGSim2D.Hosting;

/// <summary>
/// Names what a server leaves on the machine while it runs (<c>urwpgsim2d-PID-…</c>: its temporary
/// folder, its hosts' control groups), so that what a server killed before it could clean up left
/// behind is known to the next one: the PID in the name is no longer a running process.
/// </summary>
internal static class LeftBehind
{
    /// <summary>The start of every such name.</summary>
    public const string Prefix = "urwpgsim2d-";

    /// <summary>This process's name for a thing: <c>urwpgsim2d-PID-</c> followed by <paramref name="suffix"/>.</summary>
    public static string Name(string suffix) => Prefix + Environment.ProcessId.ToString(CultureInfo.InvariantCulture) + "-" + suffix;

    /// <summary>Whether <paramref name="name"/> is such a name of a server that no longer runs (never this process).</summary>
    /// <param name="name">A folder's name.</param>
    /// <param name="running">Whether a process with this id runs now.</param>
    public static bool ByEndedServer(string name, Func<int, bool> running)
    {
        if (!name.StartsWith(Prefix, StringComparison.Ordinal))
        {
            return false;
        }

        int dash = name.IndexOf('-', Prefix.Length);
        return dash > Prefix.Length
            && int.TryParse(name.AsSpan(Prefix.Length, dash - Prefix.Length), NumberStyles.None, CultureInfo.InvariantCulture, out int pid)
            && pid != Environment.ProcessId
            && !running(pid);
    }

    /// <summary>Whether a process with this id runs now (Linux: it has a folder in /proc).</summary>
    public static bool Running(int pid) => Directory.Exists("/proc/" + pid.ToString(CultureInfo.InvariantCulture));
}
