namespace URWPGSim2D.Hosting;

/// <summary>
/// Sends what a strategy prints to its team's <see cref="StrategyLog"/>. The console is one per
/// process, so <see cref="Install"/> puts a router in front of <c>Console.Out</c>, <c>Console.Error</c> and
/// <c>System.Diagnostics.Debug</c> (and <c>Trace</c>) once: text written on a thread that is running a strategy's call
/// (<see cref="Enter"/>) goes to that call's log, everything else goes where it went before. Output of
/// threads a strategy starts itself is not its call's and goes to the console.
/// </summary>
internal sealed class ConsoleRouter : TextWriter
{
    private static int s_installed;
    private static TextWriter? s_printed; // the server's standard error, where a strategy's unlogged output goes (as a host's does)

    [ThreadStatic]
    private static StrategyLog? t_current;

    [ThreadStatic]
    private static bool t_calling;

    private readonly TextWriter _fallback;

    private ConsoleRouter(TextWriter fallback) => _fallback = fallback;

    /// <inheritdoc/>
    public override Encoding Encoding => _fallback.Encoding;

    /// <summary>Routes the process's console and Debug output through the router (once per process).</summary>
    public static void Install()
    {
        if (Interlocked.Exchange(ref s_installed, 1) == 1)
        {
            return;
        }

        s_printed = TextWriter.Synchronized(Console.Error);
        Console.SetOut(TextWriter.Synchronized(new ConsoleRouter(Console.Out)));
        Console.SetError(TextWriter.Synchronized(new ConsoleRouter(Console.Error)));
        System.Diagnostics.Trace.Listeners.Add(new DebugRouter()); // Debug's and Trace's output reach Trace.Listeners
    }

    /// <summary>
    /// Starts a strategy call on the calling thread: what it prints goes to <paramref name="log"/>,
    /// or, with none, to the server's standard error (as a strategy host's output does) with its
    /// control characters escaped (<c>\u001b</c>), so that no strategy's text reaches a terminal as
    /// an escape sequence.
    /// </summary>
    public static void Enter(StrategyLog? log)
    {
        t_current = log;
        t_calling = true;
    }

    /// <summary>Ends the calling thread's strategy call.</summary>
    public static void Exit()
    {
        t_current = null;
        t_calling = false;
    }

    // A strategy's text for the console: each line's control characters escaped, the line breaks kept.
    private static string Safe(string text)
    {
        foreach (char c in text)
        {
            if (char.IsControl(c) && c != '\n')
            {
                return string.Join('\n', Array.ConvertAll(text.Split('\n'), Engine.Messages.MessageText.Escape));
            }
        }

        return text;
    }

    /// <inheritdoc/>
    public override void Write(char value)
    {
        if (t_current is { } log)
        {
            log.Append([value]);
        }
        else if (t_calling)
        {
            s_printed!.Write(Safe(value.ToString()));
        }
        else
        {
            _fallback.Write(value);
        }
    }

    /// <inheritdoc/>
    public override void Write(string? value)
    {
        if (t_current is { } log)
        {
            log.Append(value);
        }
        else if (t_calling)
        {
            s_printed!.Write(Safe(value ?? string.Empty));
        }
        else
        {
            _fallback.Write(value);
        }
    }

    /// <inheritdoc/>
    public override void Write(char[] buffer, int index, int count)
    {
        if (t_current is { } log)
        {
            log.Append(buffer.AsSpan(index, count));
        }
        else if (t_calling)
        {
            s_printed!.Write(Safe(new string(buffer, index, count)));
        }
        else
        {
            _fallback.Write(buffer, index, count);
        }
    }

    /// <inheritdoc/>
    public override void Write(ReadOnlySpan<char> buffer)
    {
        if (t_current is { } log)
        {
            log.Append(buffer);
        }
        else if (t_calling)
        {
            s_printed!.Write(Safe(buffer.ToString()));
        }
        else
        {
            _fallback.Write(buffer);
        }
    }

    /// <inheritdoc/>
    public override void WriteLine(string? value)
    {
        if (t_current is { } log)
        {
            log.Append(value);
            log.Append("\n");
        }
        else if (t_calling)
        {
            s_printed!.WriteLine(Safe(value ?? string.Empty));
        }
        else
        {
            _fallback.WriteLine(value);
        }
    }

    /// <inheritdoc/>
    public override void Flush() => _fallback.Flush();

    // System.Diagnostics.Debug's (and Trace's) output of a strategy call goes to its log; the other
    // listeners (the default one) still get everything.
    private sealed class DebugRouter : TraceListener
    {
        public override void Write(string? message) => t_current?.Append(message);

        public override void WriteLine(string? message)
        {
            if (t_current is { } log)
            {
                log.Append(message);
                log.Append("\n");
            }
        }
    }
}
