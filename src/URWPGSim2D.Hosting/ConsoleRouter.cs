using System;
using System.Diagnostics;
using System.IO;
using System.Text;
using System.Threading;
using URWPGSim2D.Engine.Teams;

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

    [ThreadStatic]
    private static StrategyLog? t_current;

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

        Console.SetOut(TextWriter.Synchronized(new ConsoleRouter(Console.Out)));
        Console.SetError(TextWriter.Synchronized(new ConsoleRouter(Console.Error)));
        System.Diagnostics.Trace.Listeners.Add(new DebugRouter()); // Debug's and Trace's output reach Trace.Listeners
    }

    /// <summary>Makes <paramref name="log"/> the log of the calling thread's strategy call.</summary>
    public static void Enter(StrategyLog log) => t_current = log;

    /// <summary>Ends the calling thread's strategy call.</summary>
    public static void Exit() => t_current = null;

    /// <inheritdoc/>
    public override void Write(char value)
    {
        if (t_current is { } log)
        {
            log.Append([value]);
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
