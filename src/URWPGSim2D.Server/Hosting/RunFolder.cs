using System;
using System.IO;
using System.Threading;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// This run's private temporary folder (<c>$TMPDIR/urwpgsim2d-PID-RANDOM</c>): strategies compiled
/// once per run and each host's scratch folder. Deleted when the program exits.
/// </summary>
internal static class RunFolder
{
    private static readonly Lazy<string> Root = new(Create);
    private static int _next;

    /// <summary>The run's folder (made on first use).</summary>
    public static string Path => Root.Value;

    /// <summary>A new empty folder for one host's scratch.</summary>
    public static string NewScratch() => Make("scratch-" + Interlocked.Increment(ref _next).ToString(System.Globalization.CultureInfo.InvariantCulture));

    /// <summary>A new empty folder for a compiled strategy.</summary>
    public static string NewStrategyFolder() => Make("strategy-" + Interlocked.Increment(ref _next).ToString(System.Globalization.CultureInfo.InvariantCulture));

    /// <summary>Deletes a folder and its contents, quietly (a host may have left read-only files).</summary>
    public static void Delete(string folder)
    {
        try
        {
            Directory.Delete(folder, recursive: true);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // left for the run's cleanup
        }
    }

    private static string Make(string name)
    {
        string folder = System.IO.Path.Combine(Path, name);
        Directory.CreateDirectory(folder);
        return folder;
    }

    private static string Create()
    {
        string root = System.IO.Path.Combine(System.IO.Path.GetTempPath(), $"urwpgsim2d-{Environment.ProcessId}-{Guid.NewGuid():N}"[..40]);
        var info = Directory.CreateDirectory(root);
        if (!OperatingSystem.IsWindows())
        {
            // Only this user: another user's process cannot read the compiled strategies or a host's scratch.
            // (A sandboxed host's "nobody" is this user outside the sandbox.)
            File.SetUnixFileMode(root, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
        }

        AppDomain.CurrentDomain.ProcessExit += (_, _) => Delete(info.FullName);
        return info.FullName;
    }
}
