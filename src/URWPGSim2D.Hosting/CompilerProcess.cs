namespace URWPGSim2D.Hosting;

/// <summary>
/// Compiles a team's strategy sources in a child process of its own (<c>dotnet URWPGSim2D.Server.dll
/// --compile-strategy …</c>), never in the server: sources can make the compiler take any amount of
/// memory and time (string constants that double, say), so it runs as a strategy host does: in the
/// host's sandbox where there is one (bubblewrap; reading only the runtime, the server's program
/// folder and the strategy's own sources, writing only its output folder), in a control group of its
/// own with the host's memory and process limits, its GC heap limited to <c>--strategy-memory</c>, and
/// at most <see cref="TimeLimitSeconds"/> of CPU and of wall time. Without a control group its address
/// space is limited instead (<c>prlimit --as</c>). The server reads back a bounded answer: the image
/// (at most <see cref="ImageLimitMb"/> MiB, written to a file of the run's folder) or the compile
/// errors as the in-process compiler words them; a compiler past a limit is one line that names it.
/// </summary>
public static class CompilerProcess
{
    /// <summary>The program's first argument that runs the compiler child (not a command of the CLI).</summary>
    public const string Command = "--compile-strategy";

    /// <summary>CPU and wall time a compilation may take, s.</summary>
    public const int TimeLimitSeconds = 60;

    /// <summary>The largest compiled image accepted, MiB.</summary>
    public const int ImageLimitMb = 64;

    /// <summary>Address space of a compiler without a control group beyond its heap limit: the runtime's reservations, code and stacks, MiB.</summary>
    public const int AddressSpaceMb = 3072;

    private const int OutOfMemoryExit = 6;
    private const string NotePrefix = "note ";
    private const int Failed = 1;
    private const int AnswerLines = 4096;
    private const int LineLimit = 4096;
    private const int TailLines = 4;

    /// <summary>
    /// Compiles <paramref name="files"/> of <paramref name="path"/> into the assembly <paramref name="name"/>
    /// in a compiler child limited by <paramref name="settings"/>.
    /// </summary>
    /// <param name="name">The assembly name.</param>
    /// <param name="path">The spec's folder or file, as the user wrote it (the sandbox may read it).</param>
    /// <param name="files">Its source files.</param>
    /// <param name="settings">The sandbox mode and the memory and process limits.</param>
    /// <param name="note">Told the compiler's notes (a source read as GB18030), one line each.</param>
    /// <param name="timeLimitSeconds">CPU and wall time the compilation may take, s (<see cref="TimeLimitSeconds"/>; tests set less).</param>
    /// <param name="started">Told the process ID of the compiler child as soon as it has started, or null.</param>
    /// <returns>The image, and the file of the run's folder that holds it.</returns>
    /// <exception cref="StrategyLoadException">The sources do not compile, or the compiler went past a limit (one line naming it).</exception>
    public static (byte[] Image, string File) Compile(string name, string path, IReadOnlyList<string> files, HostSettings settings, Action<string>? note = null, int timeLimitSeconds = TimeLimitSeconds, Action<int>? started = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(timeLimitSeconds, 1);
        bool sandbox = HostSandbox.Use(settings.Sandbox);
        string scratch = RunFolder.NewScratch();
        string output = RunFolder.NewStrategyFolder();
        string image = Path.Combine(output, name + ".dll");
        bool done = false;
        var cgroup = HostCgroup.Create(settings);
        try
        {
            var result = Run(name, path, files, settings, sandbox, cgroup, scratch, image, note, timeLimitSeconds, started);
            done = true;
            return (result, image);
        }
        finally
        {
            cgroup?.Dispose();
            RunFolder.Delete(scratch);
            if (!done)
            {
                RunFolder.Delete(output);
            }
        }
    }

    private static byte[] Run(string name, string path, IReadOnlyList<string> files, HostSettings settings, bool sandbox, SandboxCgroup? cgroup, string scratch, string image, Action<string>? note, int timeLimitSeconds, Action<int>? started)
    {
        string server = HostProcess.ServerAssembly;
        List<string>? bubblewrap = null;
        if (sandbox)
        {
            var readOnly = new List<string> { HostProcess.DotnetRoot(), Path.GetDirectoryName(server)!, Path.GetFullPath(path) };
            bubblewrap = Sandbox.Arguments(readOnly, scratch, HostProcess.ChildEnvironment(scratch, settings.MemoryMb), (long)settings.ScratchMb * 1024 * 1024, [Path.GetDirectoryName(image)!]);
        }

        var program = new List<string> { HostProcess.DotnetProgram, server, Command, name, Path.GetFullPath(image) };
        foreach (string file in files)
        {
            program.Add(file);
            program.Add(Path.GetFullPath(file));
        }

        // Without a control group the address space bounds the compiler's memory instead.
        long addressSpace = cgroup is null ? ((long)settings.MemoryMb + AddressSpaceMb) * 1024 * 1024 : 0;
        var start = SandboxCommand.Create(cgroup, bubblewrap, timeLimitSeconds, addressSpace, program, scratch, HostProcess.ChildEnvironment(scratch, settings.MemoryMb));
        using var process = SandboxedProcess.Start(start) ?? throw new StrategyLoadException("the compiler did not start");
        started?.Invoke(process.Id);
        process.StandardInput.Close();
        using var timeLimit = new TimeLimit(TimeSpan.FromSeconds(timeLimitSeconds), cgroup, () => End(process, cgroup));
        var tail = new List<string>();
        var errors = new Thread(() => ReadLines(process.StandardError.BaseStream, tail, TailLines, keepLast: true)) { IsBackground = true, Name = "compiler stderr" };
        errors.Start();
        var answer = new List<string>();
        ReadLines(process.StandardOutput.BaseStream, answer, AnswerLines, keepLast: false);
        process.WaitForExit();
        timeLimit.Stop();
        errors.Join(2000);
        int code = process.ExitCode;

        if (timeLimit.Passed || code == 128 + HostProcess.CpuLimitSignal)
        {
            throw new StrategyLoadException(string.Create(CultureInfo.InvariantCulture, $"the compiler took longer than its time limit of {timeLimitSeconds} s, stopped"));
        }

        string stderr;
        lock (tail)
        {
            stderr = string.Join(" | ", tail);
        }

        if (code == OutOfMemoryExit || (cgroup is not null && cgroup.OutOfMemory()) || stderr.Contains("OutOfMemory", StringComparison.Ordinal) || stderr.Contains("Out of memory", StringComparison.OrdinalIgnoreCase))
        {
            throw new StrategyLoadException($"the compiler ran out of memory: its limit is {settings.MemoryMb} MiB (--strategy-memory)");
        }

        int notes = 0;
        while (notes < answer.Count && answer[notes].StartsWith(NotePrefix, StringComparison.Ordinal))
        {
            note?.Invoke(Engine.Messages.MessageText.Escape(answer[notes][NotePrefix.Length..]));
            notes++;
        }

        answer.RemoveRange(0, notes);
        if (code == 0 && answer.Count == 1 && answer[0] == "ok")
        {
            return ReadImage(image);
        }

        if (code == Failed && answer.Count >= 2 && answer[0] == "error")
        {
            throw new StrategyLoadException(answer[1], answer.GetRange(2, answer.Count - 2));
        }

        string how = SandboxedProcess.DescribeExit(code);
        throw new StrategyLoadException(stderr.Length == 0 ? $"the compiler ended unexpectedly ({how})" : $"the compiler ended unexpectedly ({how}): {stderr}");
    }

    // The image the compiler wrote, if it is a regular file within the size limit.
    private static byte[] ReadImage(string image)
    {
        var info = new FileInfo(image);
        if (!info.Exists || info.LinkTarget is not null || info.Length > (long)ImageLimitMb * 1024 * 1024)
        {
            throw new StrategyLoadException($"the compiler left no image within the limit of {ImageLimitMb} MiB");
        }

        return File.ReadAllBytes(image);
    }

    private static void End(Process process, SandboxCgroup? cgroup) => SandboxedProcess.Kill(process, cgroup);

    // The compiler's wall-time limit, counted as a host's waits are (HostWatchdog.Overdue): its own
    // wall time (the time its sandbox waited for a CPU taken off) or its sandbox's CPU time, and at
    // most five times the limit in wall time; looked at when the limit is reached, and again every
    // Recheck while a busy machine has kept it waiting.
    private sealed class TimeLimit : IDisposable
    {
        private static readonly TimeSpan Recheck = TimeSpan.FromMilliseconds(250);
        private readonly Stopwatch _wall = Stopwatch.StartNew();
        private readonly TimeSpan _limit;
        private readonly SandboxCgroup? _cgroup;
        private readonly Action _end;
        private readonly Timer _timer;
        private int _passed;
        private int _stopped;

        public TimeLimit(TimeSpan limit, SandboxCgroup? cgroup, Action end)
        {
            _limit = limit;
            _cgroup = cgroup;
            _end = end;
            _timer = new Timer(Check, null, limit, Timeout.InfiniteTimeSpan);
        }

        // Whether the compiler was stopped at its limit.
        public bool Passed => Volatile.Read(ref _passed) == 1;

        // The compilation is over: no more looks.
        public void Stop()
        {
            Volatile.Write(ref _stopped, 1);
            _timer.Change(Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
        }

        public void Dispose() => _timer.Dispose();

        private void Check(object? state)
        {
            if (Volatile.Read(ref _stopped) == 1)
            {
                return;
            }

            if (HostWatchdog.Overdue(_wall.Elapsed, _limit, _cgroup?.WaitingTime(), _cgroup?.CpuTime()))
            {
                Volatile.Write(ref _passed, 1);
                _end();
                return;
            }

            try
            {
                _timer.Change(Recheck, Timeout.InfiniteTimeSpan);
            }
            catch (ObjectDisposedException)
            {
                // the compilation is over
            }
        }
    }

    // Reads the stream to its end as UTF-8 lines, each cut to LineLimit characters; keeps the first
    // (or the last) `most` lines and drops the rest, so whatever the child writes, this holds little.
    private static void ReadLines(Stream stream, List<string> lines, int most, bool keepLast)
    {
        var buffer = new byte[4096];
        var chars = new char[buffer.Length + 4];
        var decoder = new UTF8Encoding(false).GetDecoder();
        var line = new StringBuilder();
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
                        Keep(lines, line, most, keepLast);
                    }
                    else if (c != '\r' && line.Length < LineLimit)
                    {
                        line.Append(c);
                    }
                }
            }
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException)
        {
            // the child has gone
        }

        if (line.Length > 0)
        {
            Keep(lines, line, most, keepLast);
        }
    }

    private static void Keep(List<string> lines, StringBuilder line, int most, bool keepLast)
    {
        lock (lines)
        {
            if (lines.Count < most)
            {
                lines.Add(line.ToString());
            }
            else if (keepLast)
            {
                lines.RemoveAt(0);
                lines.Add(line.ToString());
            }
        }

        line.Clear();
    }

    /// <summary>
    /// The compiler child: <c>--compile-strategy NAME IMAGE (FILE READ-FROM)…</c>. Compiles the files
    /// (each shown as FILE in errors, read from READ-FROM) and writes the image to IMAGE; answers on
    /// standard output <c>ok</c>, or <c>error</c>, the message and the detail lines (exit 1), after a
    /// <c>note LINE</c> for each note of the compiler.
    /// </summary>
    /// <param name="args">The arguments after <see cref="Command"/>.</param>
    /// <returns>The exit code: 0 compiled, 1 not, 2 bad arguments, 6 out of memory.</returns>
    public static int Child(ReadOnlySpan<string> args)
    {
        using var answer = new StreamWriter(Console.OpenStandardOutput(), new UTF8Encoding(false)) { NewLine = "\n" };
        if (args.Length < 4 || args.Length % 2 != 0)
        {
            answer.WriteLine("error");
            answer.WriteLine($"usage: {Command} NAME IMAGE (FILE READ-FROM)...");
            return 2;
        }

        var files = new List<string>();
        var readFrom = new List<string>();
        for (int i = 2; i < args.Length; i += 2)
        {
            files.Add(args[i]);
            readFrom.Add(args[i + 1]);
        }

        try
        {
            byte[] image = StrategyCompiler.Compile(args[0], files, line => answer.WriteLine(NotePrefix + line), readFrom);
            if (image.Length > (long)ImageLimitMb * 1024 * 1024)
            {
                throw new StrategyLoadException(string.Create(CultureInfo.InvariantCulture, $"the compiled image is {image.Length / (1024 * 1024)} MiB, more than the limit of {ImageLimitMb} MiB"));
            }

            File.WriteAllBytes(args[1], image);
            answer.WriteLine("ok");
            return 0;
        }
        catch (StrategyLoadException e)
        {
            answer.WriteLine("error");
            foreach (string line in e.Lines)
            {
                answer.WriteLine(line);
            }

            return Failed;
        }
        catch (OutOfMemoryException)
        {
            return OutOfMemoryExit;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            answer.WriteLine("error");
            answer.WriteLine(Engine.Messages.MessageText.Escape("cannot write the compiled image: " + e.Message));
            return Failed;
        }
    }
}
