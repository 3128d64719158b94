namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// What ends a strategy host, and what its fault report then says: a host lives until its match is
/// over, whichever thread of the server started it (bubblewrap's <c>--die-with-parent</c> follows the
/// starting thread, and the runtime retires idle threads of its pool); a host that reaches its CPU-time
/// limit is reported as out of CPU time, with the limit.
/// </summary>
public sealed class HostLifetimeTests() : TempFolderTest("urwpg-lifetime-")
{
    [Fact]
    public void A_host_started_by_a_thread_that_has_ended_lives_on_until_it_ends_itself()
    {
        Assert.Null(Sandbox.Unavailable);
        HostProcess? host = null;
        string? task = null;
        var starter = new Thread(() =>
        {
            task = "/proc/" + new FileInfo("/proc/thread-self").LinkTarget;
            host = HostProcess.StartWaiting([], sandbox: true, HostSettings.Default);

            // Its sandbox is set up (bubblewrap has bound the sandbox's life to its parent's) once
            // the host's runtime runs inside it.
            WaitFor(() => RuntimeRunsUnder(host.ProcessId), "the host's runtime to start in its sandbox");
        }) { Name = "short-lived host starter" };
        starter.Start();
        starter.Join();
        Assert.NotNull(host);
        using (host)
        {
            // The thread is gone in the kernel too: whatever its end signals to its children is sent.
            WaitFor(() => !Directory.Exists(task), "the starting thread to end");

            // No strategy line: a waiting host ends by itself, as disconnected (not killed).
            host.ToClient.Close();
            host.Finish(Timeout.Infinite);
            Assert.Equal($"exit code {HostCommand.Disconnected}", host.Ending());
        }
    }

    [Fact]
    public void A_host_at_its_cpu_time_limit_is_reported_out_of_cpu_time_with_the_limit()
    {
        Assert.Null(Sandbox.Unavailable);
        string file = SdkStrategy.Write(Folder, "Spinner", "Spinner", string.Empty, members: "public Spinner() { while (true) { } }");
        using var host = HostProcess.Start(file, [file], sandbox: true, HostSettings.Default, cpuSeconds: 1);
        host.Finish(Timeout.Infinite);
        Assert.StartsWith("out of CPU time: it reached its limit of 1 s of CPU time for the match (SIGXCPU), killed", host.Ending(), StringComparison.Ordinal);
    }

    // Whether a .NET runtime runs among the descendants of the process (the sandbox's processes).
    private static bool RuntimeRunsUnder(int pid)
    {
        foreach (int child in Children(pid))
        {
            string command;
            try
            {
                command = File.ReadAllText($"/proc/{child}/cmdline");
            }
            catch (IOException)
            {
                continue; // ended meanwhile
            }

            if (command.Contains(HostProcess.ServerAssembly, StringComparison.Ordinal) || RuntimeRunsUnder(child))
            {
                return true;
            }
        }

        return false;
    }

    private static IEnumerable<int> Children(int pid)
    {
        string text;
        try
        {
            text = File.ReadAllText($"/proc/{pid}/task/{pid}/children");
        }
        catch (IOException)
        {
            return [];
        }

        return text.Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(c => int.Parse(c, CultureInfo.InvariantCulture));
    }

    // Waits for a condition (not for a time); five minutes of not seeing it is a failure.
    private static void WaitFor(Func<bool> condition, string what)
    {
        var waited = Stopwatch.StartNew();
        while (!condition())
        {
            Assert.True(waited.Elapsed < TimeSpan.FromMinutes(5), $"waited five minutes for {what}");
            Thread.Sleep(5);
        }
    }
}
