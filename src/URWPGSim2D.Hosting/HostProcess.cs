using System.Runtime.InteropServices;
using URWPGSim2D.Engine.Messages;

namespace URWPGSim2D.Hosting;

/// <summary>
/// One strategy host process (<c>host SPEC</c> of this program) with its pipes: sandboxed by
/// bubblewrap when asked and available, with an empty environment but for what .NET needs, its GC
/// heap limited, CPU time and core dumps limited by <c>prlimit</c>, and its scratch folder as working
/// directory; where cgroups allow, in a control group of its own (<see cref="SandboxCgroup"/>) that
/// limits the memory and the processes of its whole sandbox and ends all of them with it. A watchdog
/// kills it when an answer takes longer than the server allows. What it writes to standard error (what
/// its strategy prints) goes on, line by line, to the server's standard error, and its last lines are
/// kept for the fault report.
/// </summary>
public sealed class HostProcess : IStrategyLink
{
    private const int TailLines = 4;
    private const int LineLimit = 300;
    private const int EchoLimit = StrategyLog.MaxChars;
    private readonly Process _process;
    private readonly SandboxCgroup? _cgroup;
    private int _disposed;
    private readonly Queue<string> _tail = new();
    private readonly Thread _errors;
    private long _deadline = long.MaxValue; // Environment.TickCount64 by which the armed host must answer
    private volatile bool _killedByWatchdog;
    private TimeSpan _armed;
    private long _armedAt; // Environment.TickCount64 when the wait began
    private long _cpuRead, _stalledRead; // ticks: the sandbox's CPU time and CPU wait when last read (CpuTime, WaitingTime)
    private long _cpuAtWait, _stalledAtWait; // the same when the wait began
    private const long NotMeasured = -1;
    private bool _remembered;
    private int _cpuSeconds;

    private HostProcess(Process process, SandboxCgroup? cgroup, string scratch, bool sandboxed, bool waiting, int cpuSeconds)
    {
        _process = process;
        _cpuSeconds = cpuSeconds;
        (_cpuRead, _stalledRead) = cgroup is null ? (NotMeasured, NotMeasured) : (0, 0); // a new group counts from 0
        Waiting = waiting;
        _cgroup = cgroup;
        Scratch = scratch;
        Sandboxed = sandboxed;
        HostWatchdog.Watch(this);
        _errors = new Thread(ReadErrors) { IsBackground = true, Name = "strategy host stderr" };
        _errors.Start();
    }

    /// <summary>The stream to the host (its standard input).</summary>
    public Stream ToClient => _process.StandardInput.BaseStream;

    /// <summary>The stream from the host (its standard output).</summary>
    public Stream FromClient => _process.StandardOutput.BaseStream;

    /// <summary>False: a host that does not answer in time is killed (it measures its strategy's deadline itself).</summary>
    public bool SurvivesLateAnswer => false;

    /// <inheritdoc/>
    public bool CutByWait => _killedByWatchdog;

    /// <inheritdoc/>
    public TimeSpan? CpuTime() => Remember(_cgroup?.CpuTime(), ref _cpuRead);

    /// <inheritdoc/>
    public TimeSpan? WaitingTime() => Remember(_cgroup?.WaitingTime(), ref _stalledRead);

    /// <inheritdoc/>
    public long? PeakMemoryBytes() => _cgroup?.PeakMemoryBytes();

    /// <summary>The host's private scratch folder (its working directory).</summary>
    public string Scratch { get; }

    /// <summary>Whether it runs in the bubblewrap sandbox.</summary>
    public bool Sandboxed { get; }

    /// <summary>Whether it was started waiting for its strategy (<see cref="StartWaiting"/>).</summary>
    public bool Waiting { get; }

    /// <summary>
    /// Starts a host that waits for its strategy (<c>host -</c>): the runtime starts and warms up now,
    /// and <see cref="HandOver"/> names the strategy later. Its sandbox is the one of a host started for
    /// the strategy (it may read <paramref name="readOnly"/>); its CPU time is limited at the hand-over.
    /// </summary>
    /// <param name="readOnly">Files and folders of the strategy the host may read.</param>
    /// <param name="sandbox">Whether to use bubblewrap (the caller has checked it works).</param>
    /// <param name="settings">As for <see cref="Start"/>.</param>
    public static HostProcess StartWaiting(IEnumerable<string> readOnly, bool sandbox, HostSettings settings) =>
        Start(WaitingSpec, readOnly, sandbox, settings, WaitingCpuSeconds);

    /// <summary>What a waiting host is started with instead of a SPEC: it reads <c>CPU-SECONDS SPEC</c> from its first line of standard input.</summary>
    public const string WaitingSpec = "-";

    /// <summary>CPU time limit of a waiting host until its hand-over sets the match's, s.</summary>
    public const int WaitingCpuSeconds = 3600;

    /// <summary>
    /// Gives a waiting host (<see cref="StartWaiting"/>) its strategy: the line <c>CPU-SECONDS SPEC</c>.
    /// False when the host has gone meanwhile (the caller then starts a fresh one).
    /// </summary>
    /// <param name="loadSpec">What the host loads (a .dll, optionally #Type).</param>
    /// <param name="cpuSeconds">CPU time limit of the whole host for its match, s (at most <see cref="WaitingCpuSeconds"/>, the limit it was started with).</param>
    public bool HandOver(string loadSpec, int cpuSeconds)
    {
        if (!Waiting || _process.HasExited)
        {
            return false;
        }

        try
        {
            ToClient.Write(Encoding.UTF8.GetBytes(string.Create(System.Globalization.CultureInfo.InvariantCulture, $"{cpuSeconds} {loadSpec}\n")));
            ToClient.Flush();
            _cpuSeconds = Math.Min(cpuSeconds, WaitingCpuSeconds); // a process cannot raise its own limit past the one it was started with
            return true;
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException)
        {
            return false;
        }
    }

    /// <summary>Starts a host for the strategy <paramref name="loadSpec"/>.</summary>
    /// <param name="loadSpec">What the host loads (a .dll, optionally #Type).</param>
    /// <param name="readOnly">Files and folders of the strategy the host may read.</param>
    /// <param name="sandbox">Whether to use bubblewrap (the caller has checked it works).</param>
    /// <param name="settings">The heap limit, the size of scratch and /tmp, the process limit.</param>
    /// <param name="cpuSeconds">CPU time limit of the whole host, s.</param>
    public static HostProcess Start(string loadSpec, IEnumerable<string> readOnly, bool sandbox, HostSettings settings, int cpuSeconds)
    {
        string scratch = RunFolder.NewScratch();
        string server = ServerAssembly;
        string dotnetRoot = DotnetRoot();
        var environment = ChildEnvironment(scratch, settings.MemoryMb);

        var cgroup = HostCgroup.Create(settings);
        List<string>? bubblewrap = null;
        if (sandbox)
        {
            var paths = new List<string>(readOnly) { dotnetRoot, Path.GetDirectoryName(server)! };
            bubblewrap = Sandbox.Arguments(paths, scratch, environment, (long)settings.ScratchMb * 1024 * 1024);
        }

        var start = SandboxCommand.Create(cgroup, bubblewrap, cpuSeconds, 0, [DotnetProgram, server, "host", loadSpec], scratch, environment);
        Process process;
        try
        {
            process = SandboxedProcess.Start(start) ?? throw new InvalidOperationException("the strategy host did not start");
        }
        catch
        {
            cgroup?.Dispose();
            RunFolder.Delete(scratch);
            throw;
        }

        return new HostProcess(process, cgroup, scratch, sandbox, loadSpec == WaitingSpec, cpuSeconds);
    }

    /// <summary>
    /// Kills the host (<see cref="HostWatchdog"/>) if no <see cref="EndWait"/> comes within
    /// <paramref name="limit"/> of its own time: wall time less the time its sandbox waited for a
    /// CPU, or its sandbox's CPU time (<see cref="HostWatchdog.Overdue"/>). The time its sandbox had
    /// used and waited when last read (<see cref="CpuTime"/>, <see cref="WaitingTime"/>; the caller
    /// reads them after each answer) is where the wait's count starts: no reading here.
    /// </summary>
    public void BeginWait(TimeSpan limit)
    {
        _armed = limit;
        long now = Environment.TickCount64;
        _armedAt = now;
        _cpuAtWait = Volatile.Read(ref _cpuRead);
        _stalledAtWait = Volatile.Read(ref _stalledRead);
        Volatile.Write(ref _deadline, now + (long)limit.TotalMilliseconds);
    }

    /// <summary>Stops the watchdog. The first time (the host has answered, so its sandbox is up) its control group notes the sandbox's processes (<see cref="SandboxCgroup.Remember"/>).</summary>
    public void EndWait()
    {
        Volatile.Write(ref _deadline, long.MaxValue);
        if (!_remembered)
        {
            _remembered = true;
            _cgroup?.Remember();
        }
    }

    /// <summary>
    /// Whether the host is armed, its deadline has passed at <paramref name="now"/>
    /// (<see cref="Environment.TickCount64"/>) and it is <see cref="HostWatchdog.Overdue"/> (read from
    /// its sandbox's control group only then).
    /// </summary>
    public bool IsLate(long now)
    {
        if (now <= Volatile.Read(ref _deadline))
        {
            return false;
        }

        var wall = TimeSpan.FromMilliseconds(now - _armedAt);
        TimeSpan? stalled = Since(_stalledAtWait, _cgroup?.WaitingTime());
        TimeSpan? cpu = Since(_cpuAtWait, _cgroup?.CpuTime());
        return HostWatchdog.Overdue(wall, _armed, stalled, cpu);
    }

    // What a reading of the sandbox's time has grown since the wait began, or null where it is not measured.
    private static TimeSpan? Since(long atWait, TimeSpan? now) => atWait != NotMeasured && now is { } t ? t - TimeSpan.FromTicks(atWait) : null;

    // Keeps a reading of the sandbox's time for the next wait's start, and returns it.
    private static TimeSpan? Remember(TimeSpan? reading, ref long read)
    {
        if (reading is { } t)
        {
            Volatile.Write(ref read, t.Ticks);
        }

        return reading;
    }

    /// <summary>Whether the host's process has ended.</summary>
    public bool HasExited => _process.HasExited;

    /// <summary>Waits up to <paramref name="ms"/> for the host to exit.</summary>
    public void Finish(int ms) => _process.WaitForExit(ms);

    /// <summary>Kills the host and everything it started.</summary>
    public void Abort() => Kill();

    /// <summary>
    /// How the host ended, for the fault report, naming the limit that ended it where one did: the
    /// watchdog's wait, its sandbox's memory, its CPU time for the match (<c>SIGXCPU</c> at the
    /// <c>prlimit</c>); otherwise the exit code or signal; then its last lines of standard error.
    /// </summary>
    public string Ending()
    {
        if (_killedByWatchdog)
        {
            return $"no answer within {_armed.TotalSeconds:0.#} s, killed";
        }

        _process.WaitForExit(2000);
        string how;
        if (!_process.HasExited)
        {
            how = "it stopped answering";
        }
        else if (_cgroup is not null && _cgroup.OutOfMemory())
        {
            how = $"out of memory: its sandbox reached its limit of {_cgroup.MemoryBytes / (1024 * 1024)} MiB, killed";
        }
        else
        {
            int code = _process.ExitCode;
            how = code == 128 + CpuLimitSignal && !OperatingSystem.IsWindows()
                ? $"out of CPU time: it reached its limit of {_cpuSeconds} s of CPU time for the match (SIGXCPU), killed"
                : SandboxedProcess.DescribeExit(code);
        }

        _ = _cgroup?.KillAll(); // whatever the host left running in its sandbox

        _errors.Join(2000); // the rest of standard error
        string tail;
        lock (_tail)
        {
            tail = string.Join(" | ", _tail);
        }

        return tail.Length == 0 ? how : $"{how}: {tail}";
    }

    /// <summary>The signal the kernel sends a process at its CPU-time limit (<c>SIGXCPU</c>).</summary>
    public const int CpuLimitSignal = 24;

    /// <summary>Kills the host and everything it started.</summary>
    public void Kill(bool byWatchdog = false)
    {
        if (byWatchdog)
        {
            _killedByWatchdog = true;
        }

        SandboxedProcess.Kill(_process, _cgroup);
    }

    /// <summary>The host's process id (bubblewrap's when sandboxed).</summary>
    public int ProcessId => _process.Id;

    /// <summary>Ends the host and everything it started and deletes its scratch folder; a second call does nothing.</summary>
    public void Dispose()
    {
        if (System.Threading.Interlocked.Exchange(ref _disposed, 1) != 0)
        {
            return;
        }

        HostWatchdog.Forget(this);
        if (!_process.WaitForExit(0))
        {
            Kill();
        }

        _process.WaitForExit(5000);
        _process.Dispose();
        _cgroup?.Dispose(); // every process of the sandbox ends with the host
        RunFolder.Delete(Scratch);
    }

    // Keeps the last lines of the host's standard error, each cut to LineLimit characters, reading
    // in blocks: however much the host writes, with or without line breaks, this holds a few lines.
    // Every line goes on to the server's standard error (each cut to EchoLimit characters).
    private void ReadErrors()
    {
        var stream = _process.StandardError.BaseStream;
        var buffer = new byte[4096];
        var line = new StringBuilder(LineLimit);
        var echo = new StringBuilder();
        var decoder = new UTF8Encoding(false).GetDecoder();
        var chars = new char[buffer.Length + 4];
        try
        {
            int read;
            while ((read = stream.Read(buffer, 0, buffer.Length)) > 0)
            {
                int count = decoder.GetChars(buffer, 0, read, chars, 0);
                for (int i = 0; i < count; i++)
                {
                    char c = chars[i];
                    if (c == '\n')
                    {
                        Keep(line);
                        Forward(echo);
                    }
                    else if (c != '\r')
                    {
                        if (line.Length < LineLimit)
                        {
                            line.Append(c);
                        }

                        if (echo.Length < EchoLimit)
                        {
                            echo.Append(c);
                        }
                    }
                }
            }
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException)
        {
            // the host has gone
        }

        if (line.Length > 0)
        {
            Keep(line);
        }

        if (echo.Length > 0)
        {
            Forward(echo);
        }
    }

    // One line of the host's standard error on to the server's.
    private static void Forward(StringBuilder line)
    {
        try
        {
            Console.Error.WriteLine(MessageText.Escape(line.ToString())); // a strategy's escape sequences never reach the terminal as themselves
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException)
        {
            // the server's standard error is closed: the line is still in the tail
        }

        line.Clear();
    }

    private void Keep(StringBuilder line)
    {
        lock (_tail)
        {
            _tail.Enqueue(line.ToString());
            if (_tail.Count > TailLines)
            {
                _tail.Dequeue();
            }
        }

        line.Clear();
    }

    /// <summary>The server's own assembly, which a host or the compiler runs (<c>dotnet URWPGSim2D.Server.dll …</c>).</summary>
    internal static string ServerAssembly => Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll");

    /// <summary>The <c>dotnet</c> program that runs this process.</summary>
    internal static string DotnetProgram => Path.Combine(DotnetRoot(), OperatingSystem.IsWindows() ? "dotnet.exe" : "dotnet");

    /// <summary>
    /// The whole environment of a child of the server that runs untrusted work (a host, the compiler):
    /// its scratch folder as <c>HOME</c> and <c>TMPDIR</c>, the runtime's settings, its GC heap limited to
    /// <paramref name="memoryMb"/> MiB, and nothing of the server's own environment.
    /// </summary>
    internal static Dictionary<string, string> ChildEnvironment(string scratch, int memoryMb) => new(StringComparer.Ordinal)
    {
        ["PATH"] = "/usr/bin:/bin",
        ["HOME"] = scratch,
        ["TMPDIR"] = scratch,
        ["DOTNET_ROOT"] = DotnetRoot(),
        ["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1",
        ["DOTNET_NOLOGO"] = "1",
        ["DOTNET_EnableDiagnostics"] = "0", // no debugger/diagnostics sockets
        ["DOTNET_gcServer"] = "0",
        ["DOTNET_GCHeapHardLimit"] = "0x" + ((long)memoryMb * 1024 * 1024).ToString("x", System.Globalization.CultureInfo.InvariantCulture),
        ["DOTNET_TieredCompilation"] = "1", // start fast; the server's own setting (off) costs a host ~0.1 s
        ["DOTNET_TieredPGO"] = "0", // no instrumented code: a host's life is too short to profit from it
        ["DOTNET_gcConcurrent"] = "0", // no background GC thread to start
    };

    /// <summary>The folder of the <c>dotnet</c> program that runs this process.</summary>
    internal static string DotnetRoot()
    {
        // .../shared/Microsoft.NETCore.App/<version>/ -> the folder of the dotnet program
        string runtime = Path.TrimEndingDirectorySeparator(RuntimeEnvironment.GetRuntimeDirectory());
        return Path.GetFullPath(Path.Combine(runtime, "..", "..", ".."));
    }
}
