using System;
using System.IO;
using URWPGSim2D.Protocol;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// The server's side of one team's strategy host: starts the host process, takes its hello, sends
/// the assignment, then each cycle sends the snapshot and reads that cycle's decisions (the
/// protocol of docs/protocol.md). The host measures the strategy's deadline itself and answers a
/// missed one as a time-out; a watchdog kills a host that does not answer at all within
/// <see cref="AnswerLimit"/>. An answer to an earlier cycle (left behind a bad line that took its
/// place) is skipped, so one bad line costs one cycle. A host that ends, is killed, or breaks the framing ends the team's
/// strategy for the match; it is not restarted (the next match starts a new one).
/// </summary>
internal sealed class HostedStrategy : IDisposable
{
    /// <summary>Wall time a host has from its start to its hello (the .NET runtime starts, the strategy is loaded and created).</summary>
    public static readonly TimeSpan StartLimit = TimeSpan.FromSeconds(30);

    private readonly HostProcess _process;
    private readonly LineChannel _channel;
    private readonly MessageWriter _writer = new();
    private readonly AssignmentMessage _assignment;
    private readonly Decision[] _answer;
    private bool _started;
    private bool _stopped;

    /// <summary>Starts the host of <paramref name="strategy"/> for the team and match of <paramref name="assignment"/>.</summary>
    public HostedStrategy(PreparedStrategy strategy, HostSettings settings, AssignmentMessage assignment, int cycles)
    {
        ArgumentNullException.ThrowIfNull(strategy);
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentNullException.ThrowIfNull(assignment);
        _assignment = assignment;
        _answer = new Decision[assignment.Fish.Length];
        AnswerLimit = ThreadTimeClock.HangLimitFor(TimeSpan.FromMilliseconds(assignment.DeadlineMs)) * 2 + TimeSpan.FromSeconds(5);

        // CPU time of the whole host: every cycle at its deadline, and a minute for the start.
        long cpu = 60 + ((long)Math.Max(cycles, 1) * assignment.DeadlineMs / 1000 * 2);
        _process = HostProcess.Start(strategy.LoadSpec, strategy.ReadOnly, HostSandbox.Use(settings.Sandbox), settings.MemoryMb, (int)Math.Min(cpu, int.MaxValue));
        _channel = new LineChannel(_process.FromHost, _process.ToHost, ProtocolLimits.ClientLineBytes);
    }

    /// <summary>What a cycle's call came to.</summary>
    public enum Outcome
    {
        /// <summary>Decisions for every fish.</summary>
        Decided,

        /// <summary>The strategy threw.</summary>
        Exception,

        /// <summary>The strategy answered something unusable, or the host broke the protocol for this cycle.</summary>
        BadAnswer,

        /// <summary>The strategy missed its deadline (or is still busy).</summary>
        TimedOut,

        /// <summary>The host ended (crashed, exited, was killed) or could not start: no more answers this match.</summary>
        Ended,
    }

    /// <summary>Wall time the server waits for a cycle's answer before it kills the host.</summary>
    public TimeSpan AnswerLimit { get; }

    /// <summary>The team name the host said hello with, or null.</summary>
    public string? TeamName { get; private set; }

    /// <summary>Whether the host has ended; every later call answers <see cref="Outcome.Ended"/>.</summary>
    public bool HasEnded { get; private set; }

    /// <summary>How the host ended when a <see cref="Outcome.BadAnswer"/> also ended it (an overlong line), else null.</summary>
    public string? EndedBy { get; private set; }

    /// <summary>Whether the host runs in the bubblewrap sandbox.</summary>
    public bool Sandboxed => _process.Sandboxed;

    /// <summary>
    /// Sends <paramref name="snapshot"/> and reads the cycle's decisions into <paramref name="decisions"/>
    /// (written only on <see cref="Outcome.Decided"/>). <paramref name="message"/> says what went wrong otherwise.
    /// </summary>
    public Outcome Decide(MatchSnapshot snapshot, Span<Decision> decisions, out string? message)
    {
        message = null;
        if (HasEnded)
        {
            message = "the strategy host has ended";
            return Outcome.Ended;
        }

        try
        {
            if (!_started && !Handshake(out message))
            {
                return End(ref message);
            }

            _channel.WriteLine(_writer.Cycle(snapshot));
            _process.Arm(AnswerLimit);
            bool read = _channel.TryReadLine(out var line);
            while (read && StaleAnswer.Is(line, snapshot.Cycle))
            {
                read = _channel.TryReadLine(out line); // an earlier cycle's answer, behind a bad line that took its place: that cycle is charged already
            }

            _process.Disarm();
            if (!read)
            {
                return End(ref message);
            }

            if (MessageReader.TypeOf(line) != MessageType.Decisions)
            {
                message = "the host answered something other than decisions";
                return Outcome.BadAnswer;
            }

            switch (MessageReader.ReadDecisions(line, snapshot.Cycle, _answer, out message))
            {
                case AnswerKind.Decided:
                    _answer.CopyTo(decisions);
                    return Outcome.Decided;
                case AnswerKind.Exception:
                    return Outcome.Exception;
                case AnswerKind.Timeout:
                    return Outcome.TimedOut;
                default:
                    return Outcome.BadAnswer;
            }
        }
        catch (ProtocolException e) when (e.Message.StartsWith("a line is longer", StringComparison.Ordinal))
        {
            // A bad answer, and the connection is closed (docs/protocol.md, "Limits"): the host ends too.
            _process.Disarm();
            _process.Kill();
            string? how = "the server closed the connection after the overlong line";
            End(ref how);
            EndedBy = how;
            message = e.Message;
            return Outcome.BadAnswer;
        }
        catch (ProtocolException e)
        {
            message = e.Message;
            return Outcome.BadAnswer;
        }
        catch (IOException)
        {
            _process.Disarm();
            return End(ref message); // its pipe broke: it has gone
        }
    }

    /// <summary>Sends the end of the match (when the host is still there) and lets the host exit; then disposes it.</summary>
    public void Stop(EndMessage end)
    {
        if (_stopped)
        {
            return;
        }

        _stopped = true;
        if (_started && !HasEnded)
        {
            try
            {
                _channel.WriteLine(_writer.End(end));
            }
            catch (IOException)
            {
                // it has gone already
            }

            _process.WaitForExit(2000);
        }

        Dispose();
    }

    /// <inheritdoc/>
    public void Dispose() => _process.Dispose();

    private bool Handshake(out string? message)
    {
        message = null;
        _process.Arm(StartLimit);
        bool read = _channel.TryReadLine(out var line);
        _process.Disarm();
        if (!read)
        {
            return false;
        }

        if (MessageReader.TypeOf(line) != MessageType.Hello)
        {
            _process.Kill();
            message = "the host did not say hello";
            return false;
        }

        var hello = MessageReader.ReadHello(line);
        if (hello.Version != ProtocolVersion.Current)
        {
            message = $"protocol version {hello.Version} is not supported (this server speaks {ProtocolVersion.Current})";
            _channel.WriteLine(_writer.Error(message));
            _process.Kill();
            return false;
        }

        TeamName = hello.Name;
        _channel.WriteLine(_writer.Assignment(_assignment));
        _started = true;
        return true;
    }

    private Outcome End(ref string? message)
    {
        HasEnded = true;
        string how = _process.KilledByWatchdog ? $"no answer within {AnswerLimit.TotalSeconds:0.#} s, killed" : _process.Ending();
        message = message is null ? how : $"{message} ({how})";
        return Outcome.Ended;
    }
}
