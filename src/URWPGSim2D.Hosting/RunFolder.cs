namespace URWPGSim2D.Hosting;

/// <summary>
/// This run's private temporary folder (<c>$TMPDIR/urwpgsim2d-PID-RANDOM</c>): strategies compiled
/// once per run and each host's scratch folder. Deleted when the program exits; the folders of
/// servers killed before they could delete theirs are deleted by the next run that makes one.
/// </summary>
internal static class RunFolder
{
    private const string LockName = ".lock";
    private static readonly Lazy<string> Root = new(Create);
    private static int _next;
    private static FileStream? _lock;

    /// <summary>The run's folder (made on first use).</summary>
    public static string Path => Root.Value;

    /// <summary>A new empty folder for one host's scratch.</summary>
    public static string NewScratch() => Make("scratch-" + Interlocked.Increment(ref _next).ToString(System.Globalization.CultureInfo.InvariantCulture));

    /// <summary>A new empty folder for a compiled strategy.</summary>
    public static string NewStrategyFolder() => Make("strategy-" + Interlocked.Increment(ref _next).ToString(System.Globalization.CultureInfo.InvariantCulture));

    /// <summary>
    /// Deletes a folder and everything in it, whatever a strategy left there: any depth (beyond the
    /// path limit), names that are not UTF-8, folders without permissions. Never throws: what cannot
    /// be deleted is one warning line (<see cref="HostSandbox.Warn"/>).
    /// </summary>
    public static void Delete(string folder)
    {
        if (TryDelete(folder) is { } problem)
        {
            HostSandbox.Warn?.Invoke($"warning: cannot delete the temporary folder {folder}: {Engine.Messages.MessageText.Escape(problem).ReplaceLineEndings(" ")}");
        }
    }

    /// <summary>
    /// Deletes the folders of this kind that servers which no longer run left in <paramref name="temp"/>
    /// (killed before they could delete them), quietly: one that cannot be deleted (another user's,
    /// say) stays.
    /// </summary>
    /// <returns>How many were deleted.</returns>
    internal static int SweepStale(string temp, Func<int, bool> running)
    {
        int deleted = 0;
        try
        {
            foreach (string folder in Directory.EnumerateDirectories(temp, LeftBehind.Prefix + "*"))
            {
                if (LeftBehind.ByEndedServer(System.IO.Path.GetFileName(folder), running) && !InUse(folder) && TryDelete(folder) is null)
                {
                    deleted++;
                }
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // a temporary folder this process may not list: nothing to sweep
        }

        return deleted;
    }

    // Whether a server still holds the folder's lock: one in another PID namespace (a container
    // sharing this temporary folder) whose process id means nothing here.
    private static bool InUse(string folder)
    {
        try
        {
            using var held = new FileStream(System.IO.Path.Combine(folder, LockName), FileMode.Open, FileAccess.Read, FileShare.None);
            return false;
        }
        catch (FileNotFoundException)
        {
            return false;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return true;
        }
    }

    // Deletes the folder; null, or why it is still there.
    private static string? TryDelete(string folder)
    {
        string? problem = null;
        try
        {
            Directory.Delete(folder, recursive: true);
            return null;
        }
        catch (DirectoryNotFoundException)
        {
            return null;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            problem = e.Message;
        }

        // What .NET cannot name or reach, the system's tools can: they work relative to each folder
        // and pass names as bytes. First give this user every permission back (a host may have taken them).
        if (!OperatingSystem.IsWindows())
        {
            Tool("/bin/chmod", "-R", "u+rwx", "--", folder);
            problem = Tool("/bin/rm", "-rf", "--", folder) ?? problem;
        }

        try
        {
            if (!Directory.Exists(folder))
            {
                return null;
            }
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            problem = e.Message;
        }

        return problem ?? "unknown reason";
    }

    // Runs a tool for up to a minute; its first line of complaint, or null.
    private static string? Tool(string program, params string[] arguments)
    {
        try
        {
            var start = new System.Diagnostics.ProcessStartInfo(program) { UseShellExecute = false, RedirectStandardError = true, RedirectStandardOutput = true };
            foreach (string argument in arguments)
            {
                start.ArgumentList.Add(argument);
            }

            using var process = System.Diagnostics.Process.Start(start);
            if (process is null)
            {
                return program + " did not start";
            }

            process.StandardOutput.Close();
            var error = process.StandardError.ReadLineAsync();
            if (!process.WaitForExit(60_000))
            {
                process.Kill(entireProcessTree: true);
                return program + " took over a minute";
            }

            return process.ExitCode == 0 ? null : error.Wait(1000) ? error.Result : null;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return e.Message;
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
        if (!OperatingSystem.IsWindows())
        {
            _ = SweepStale(System.IO.Path.GetTempPath(), LeftBehind.Running);
        }

        string root = System.IO.Path.Combine(System.IO.Path.GetTempPath(), LeftBehind.Name($"{Guid.NewGuid():N}")[..40]);
        var info = Directory.CreateDirectory(root);
        if (!OperatingSystem.IsWindows())
        {
            // Only this user: another user's process cannot read the compiled strategies or a host's scratch.
            // (A sandboxed host's "nobody" is this user outside the sandbox.)
            File.SetUnixFileMode(root, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
        }

        // Held while this process runs: the folder is in use, whatever its name says.
        _lock = new FileStream(System.IO.Path.Combine(info.FullName, LockName), FileMode.CreateNew, FileAccess.ReadWrite, FileShare.None);
        AppDomain.CurrentDomain.ProcessExit += (_, _) =>
        {
            _lock.Dispose();
            Delete(info.FullName);
        };
        return info.FullName;
    }
}
