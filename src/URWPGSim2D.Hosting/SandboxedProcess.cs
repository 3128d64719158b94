using System.Collections.Concurrent;
using System.Threading.Tasks;

namespace URWPGSim2D.Hosting;

/// <summary>Starting and ending a child process the sandbox runs (a strategy host or the compiler).</summary>
/// <remarks>
/// Every such child is started by one thread of the program's own, <see cref="StarterThreadName"/>,
/// which waits for the next start as long as the program runs. bubblewrap's
/// <c>--die-with-parent</c> ends the sandbox when its parent ends, and the kernel's parent-death
/// signal follows the thread that started the child, not the process: a host started from a thread
/// that ends before the host does (a thread of the pool, which the runtime retires after it has been
/// idle a while, more of them on a busy machine) would be killed, <c>SIGKILL</c>, in the middle of its
/// match. Started from the starter thread, a child's sandbox ends only with the program.
/// </remarks>
internal static class SandboxedProcess
{
    /// <summary>The name of the thread that starts every sandboxed child.</summary>
    public const string StarterThreadName = "sandbox starter";

    private static readonly BlockingCollection<Launch> Launches = [];
    private static readonly Lazy<Thread> Starter = new(() =>
    {
        var thread = new Thread(StartEach) { IsBackground = true, Name = StarterThreadName };
        thread.Start();
        return thread;
    });

    /// <summary>
    /// Starts <paramref name="start"/> on the starter thread and returns its process (null as
    /// <see cref="Process.Start(ProcessStartInfo)"/> returns it); what starting it throws is thrown
    /// here.
    /// </summary>
    public static Process? Start(ProcessStartInfo start)
    {
        ArgumentNullException.ThrowIfNull(start);
        var launch = new Launch(start);
        Launches.Add(launch);
        _ = Starter.Value;
        return launch.Started.Task.GetAwaiter().GetResult();
    }

    /// <summary>How a child's exit code reads in a report: the signal that ended it (Unix), or the code.</summary>
    public static string DescribeExit(int code) =>
        code > 128 && code < 160 && !OperatingSystem.IsWindows() ? $"killed by signal {code - 128}" : $"exit code {code}";

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

    // The starter thread: starts each child asked for, for as long as the program runs.
    private static void StartEach()
    {
        foreach (var launch in Launches.GetConsumingEnumerable())
        {
            try
            {
                launch.Started.SetResult(Process.Start(launch.Info));
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                launch.Started.SetException(e); // thrown to the thread that asked
            }
        }
    }

    private sealed record Launch(ProcessStartInfo Info)
    {
        public TaskCompletionSource<Process?> Started { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);
    }
}
