using System.Security.Cryptography;
using URWPGSim2D.Protocol;

namespace URWPGSim2D.Hosting;

/// <summary>
/// The server's side of the strategy protocol (docs/protocol.md) over one link, the same for a
/// strategy host's pipes and a remote client's TCP connection: takes the client's hello (its
/// version and token), sends the assignment, then each cycle sends the snapshot and reads that
/// cycle's decisions. An answer later than <see cref="AnswerLimit"/> ends a host's link (the host
/// measures its strategy's deadline itself, so only a hung host is that late) and is a time-out on
/// TCP. An answer to an earlier cycle (a late one, or one left behind a bad line that took its
/// place) is skipped: that cycle is charged already, so the client is back in step. A client that
/// ends ends the connection; what it got wrong in one answer (JSON, type, cycle, count, gears) is a
/// bad answer for that cycle, and <c>log</c> is told each one; a line over the limit is a bad
/// answer that also ends the connection.
/// </summary>
internal sealed class StrategyConnection : IConnectedStrategy
{
    private readonly IStrategyLink _link;
    private readonly LineChannel _channel;
    private readonly MessageWriter _writer = new();
    private readonly AssignmentMessage _assignment;
    private readonly byte[]? _token;
    private readonly TimeSpan _helloLimit;
    private string? _introductionFailure;
    private readonly Action<string>? _log;
    private readonly Decision[] _answer;
    private readonly string _peer;
    private readonly DebugRecorder? _drawings;
    private readonly StrategyLog? _printed;
    private readonly PrintedOutput? _printedText;
    private bool _answered;
    private bool _packed; // the client asked for packed cycles
    private bool _series; // the client plays several matches on the connection, and the server keeps it
    private bool _started;
    private bool _stopped;

    /// <summary>Creates the connection over <paramref name="link"/>; nothing is read before the first <c>Decide</c> or <see cref="Handshake"/>.</summary>
    /// <param name="link">The transport.</param>
    /// <param name="assignment">What the client is told of the match.</param>
    /// <param name="answerLimit">Wall time the server waits for a cycle's answer.</param>
    /// <param name="helloLimit">Wall time the client has for its hello.</param>
    /// <param name="token">The token the hello must carry, or null for none.</param>
    /// <param name="log">Told every refused hello and every bad answer, one line each; or null.</param>
    /// <param name="peer">What the messages call the other side: <c>the host</c>, <c>the client</c>.</param>
    /// <param name="channel">The framing of the link when it goes on from an earlier match (<see cref="Channel"/>), or null for a new one.</param>
    public StrategyConnection(IStrategyLink link, AssignmentMessage assignment, TimeSpan answerLimit, TimeSpan helloLimit, string? token, Action<string>? log, string peer = "the client", LineChannel? channel = null)
    {
        _peer = peer;
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(assignment);
        _link = link;
        _assignment = assignment;
        _answer = new Decision[assignment.Fish.Length];
        _drawings = assignment.Draw ? new DebugRecorder() : null;
        (_printed, _printedText) = assignment.Log ? (new StrategyLog(), new PrintedOutput()) : (null, null);
        _token = token is null ? null : Encoding.UTF8.GetBytes(token);
        _helloLimit = helloLimit;
        _log = log;
        AnswerLimit = answerLimit;
        _channel = channel ?? new LineChannel(link.FromClient, link.ToClient, ProtocolLimits.ClientLineBytes);
        Continued = channel is not null;
    }

    /// <summary>The framing of the link (lines read ahead stay in it), for the next match of a series (<see cref="KeepFor"/>).</summary>
    public LineChannel Channel => _channel;

    /// <summary>Whether the connection goes on from an earlier match: answers to that match that come before the hello are skipped.</summary>
    public bool Continued { get; }

    /// <summary>Whether the client plays a series and the server keeps it for its next match (both said <c>"series":true</c>).</summary>
    public bool Series => _series;

    /// <summary>Whether the server keeps a client that asks for it (<c>"series":true</c>) for its next match after <c>end</c> (a remote team).</summary>
    public bool OffersSeries { get; init; }

    /// <summary>Wall time the server waits for a cycle's answer.</summary>
    public TimeSpan AnswerLimit { get; }

    /// <summary>Wall time for the first answer after the hello (the client's code is compiled then); by default <see cref="AnswerLimit"/>.</summary>
    public TimeSpan? FirstAnswerLimit { get; init; }

    /// <summary>The link under the connection.</summary>
    public IStrategyLink Link => _link;

    /// <inheritdoc/>
    public string? TeamName { get; private set; }

    /// <summary>Whether the connection has ended; every later call answers <see cref="ConnectionOutcome.Ended"/>.</summary>
    public bool HasEnded { get; private set; }

    /// <inheritdoc/>
    public string? EndedBy { get; private set; }

    /// <summary>False: a connection's end is final (<see cref="RemoteStrategy"/> takes a new one).</summary>
    public bool Reconnects => false;

    /// <summary>
    /// Reads the client's hello and answers it: the assignment, or an <c>error</c> (another version,
    /// a wrong token, no hello) after which the link is cut. True when the client was taken.
    /// </summary>
    public bool Handshake(out string? message)
    {
        message = null;
        if (_started)
        {
            return true;
        }

        if (HasEnded)
        {
            message = "the connection has ended";
            return false;
        }

        try
        {
            _link.BeginWait(_helloLimit);
            bool read;
            ReadOnlySpan<byte> line;
            try
            {
                // After an earlier match, its late answers may come before the hello: they are skipped.
                while ((read = _channel.TryReadLine(out line)) && Continued && MessageReader.TypeOf(line) == MessageType.Decisions)
                {
                }
            }
            finally
            {
                _link.EndWait();
            }

            if (!read)
            {
                End(ref message);
                return false;
            }

            if (MessageReader.TypeOf(line) != MessageType.Hello)
            {
                return Refuse($"{_peer} did not say hello", out message);
            }

            var hello = MessageReader.ReadHello(line);
            if (hello.Version != ProtocolVersion.Current)
            {
                return Refuse($"protocol version {hello.Version} is not supported (this server speaks {ProtocolVersion.Current})", out message);
            }

            if (_token is not null && (hello.Token is null || !CryptographicOperations.FixedTimeEquals(_token, Encoding.UTF8.GetBytes(hello.Token))))
            {
                return Refuse(hello.Token is null ? "this slot needs a token" : "wrong token", out message);
            }

            TeamName = hello.Name;
            _packed = hello.Packed;
            _series = hello.Series && OffersSeries;
            _channel.WriteLine(_writer.Assignment(_packed || _series ? _assignment with { Packed = _packed, Series = _series } : _assignment));
            _started = true;
            return true;
        }
        catch (TimeoutException)
        {
            return Refuse($"no hello within {_helloLimit.TotalSeconds:0.#} s", out message);
        }
        catch (ProtocolException e)
        {
            return Refuse("hello: " + e.Message, out message);
        }
        catch (IOException)
        {
            End(ref message);
            return false;
        }
    }

    /// <summary>
    /// Takes the client's hello now, before the match (its name is then known to every output);
    /// a refused or missing hello is what the first <c>Decide</c> reports, as without this call.
    /// </summary>
    public void Introduce()
    {
        if (!_started && !HasEnded && !Handshake(out string? message))
        {
            _introductionFailure = message;
        }
    }

    /// <inheritdoc/>
    public DebugRecorder? Drawings => _drawings;

    /// <inheritdoc/>
    public StrategyLog? Log => _printed;

    /// <summary>Decides with the connection's own limit: <see cref="FirstAnswerLimit"/> for the first answer, <see cref="AnswerLimit"/> after.</summary>
    /// <param name="snapshot">What the strategy sees.</param>
    /// <param name="decisions">Where the decisions go.</param>
    /// <param name="message">What went wrong, or null.</param>
    public ConnectionOutcome Decide(MatchSnapshot snapshot, Span<Decision> decisions, out string? message) =>
        Decide(snapshot, decisions, _answered ? AnswerLimit : FirstAnswerLimit ?? AnswerLimit, out message);

    /// <inheritdoc/>
    public TimeSpan? CpuTime() => _link.CpuTime();

    /// <inheritdoc/>
    public TimeSpan? WaitingTime() => _link.WaitingTime();

    /// <inheritdoc/>
    public long? PeakMemoryBytes() => _link.PeakMemoryBytes();

    /// <inheritdoc/>
    public ConnectionOutcome Decide(MatchSnapshot snapshot, Span<Decision> decisions, TimeSpan waitLimit, out string? message)
    {
        message = null;
        EndedBy = null;
        _drawings?.Reset(_assignment.Fish);
        _printed?.Clear();
        _printedText?.Clear();
        if (HasEnded)
        {
            message = _introductionFailure ?? "the connection has ended";
            _introductionFailure = null;
            return ConnectionOutcome.Ended;
        }

        if (!_started && !Handshake(out message))
        {
            return ConnectionOutcome.Ended;
        }

        int cycle = snapshot.Cycle;
        try
        {
            _channel.WriteLine(_writer.Cycle(snapshot, _packed));
            if (!ReadAnswer(cycle, waitLimit, out var line))
            {
                var ended = End(ref message);
                return _link.CutByWait ? ConnectionOutcome.GivenUp : ended;
            }

            if (MessageReader.TypeOf(line) != MessageType.Decisions)
            {
                return Bad(cycle, $"{_peer} answered something other than decisions", out message);
            }

            var answer = MessageReader.ReadDecisions(line, cycle, _answer, out message, _drawings, _printedText);
            if (_printedText is { } printed)
            {
                _printed!.Add(printed.Text, printed.Dropped);
            }

            switch (answer)
            {
                case AnswerKind.Decided:
                    _answer.CopyTo(decisions);
                    return ConnectionOutcome.Decided;
                case AnswerKind.Exception:
                    return ConnectionOutcome.Exception;
                case AnswerKind.Timeout:
                    return ConnectionOutcome.TimedOut;
                default:
                    return Bad(cycle, message!, out message);
            }
        }
        catch (TimeoutException)
        {
            message = $"no answer within {waitLimit.TotalSeconds:0.0##} s";
            return ConnectionOutcome.GivenUp; // its answer may still come: skipped then
        }
        catch (ProtocolException e) when (e.Message.StartsWith("a line is longer", StringComparison.Ordinal))
        {
            // A bad answer, and the connection is closed (docs/protocol.md, "Limits").
            _log?.Invoke($"cycle {cycle + 1}: bad answer: {e.Message}: connection closed");
            _link.Abort();
            string? how = "the server closed the connection after the overlong line";
            End(ref how);
            EndedBy = how;
            message = e.Message;
            return ConnectionOutcome.BadAnswer;
        }
        catch (ProtocolException e)
        {
            return Bad(cycle, e.Message, out message);
        }
        catch (IOException)
        {
            return End(ref message); // its pipe or socket broke: it has gone
        }
    }

    /// <inheritdoc/>
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

            _link.Finish(2000);
        }

        Dispose();
    }

    /// <summary>
    /// Ends the match for a client that plays a series (<see cref="HelloMessage.Series"/>): sends <c>end</c> and keeps
    /// the link open for its next match (the caller owns <see cref="Link"/> and <see cref="Channel"/> then). False,
    /// and nothing done, for any other connection (<see cref="Stop"/> ends it); false too when the <c>end</c> cannot
    /// be sent (the link is closed then).
    /// </summary>
    /// <param name="end">The match's result.</param>
    public bool KeepFor(EndMessage end)
    {
        if (!_series || !_started || HasEnded || _stopped)
        {
            return false;
        }

        _stopped = true;
        try
        {
            _channel.WriteLine(_writer.End(end));
            return true;
        }
        catch (IOException)
        {
            Dispose(); // it has gone already
            return false;
        }
    }

    /// <inheritdoc/>
    public void Dispose() => _link.Dispose();

    // The cycle's answer, past answers to earlier cycles (already charged).
    private bool ReadAnswer(int cycle, TimeSpan limit, out ReadOnlySpan<byte> line)
    {
        _link.BeginWait(limit);
        _answered = true;
        try
        {
            while (true)
            {
                if (!_channel.TryReadLine(out line))
                {
                    return false;
                }

                if (!StaleAnswer.Is(line, cycle))
                {
                    return true;
                }
            }
        }
        finally
        {
            _link.EndWait();
        }
    }

    private ConnectionOutcome Bad(int cycle, string why, out string? message)
    {
        message = why;
        _log?.Invoke($"cycle {cycle + 1}: bad answer: {Engine.Messages.MessageText.Escape(why)}");
        return ConnectionOutcome.BadAnswer;
    }

    private bool Refuse(string why, out string? message)
    {
        _log?.Invoke("refused a client: " + Engine.Messages.MessageText.Escape(why));
        try
        {
            _channel.WriteLine(_writer.Error(why));
        }
        catch (IOException)
        {
            // it has gone already
        }

        _link.Abort();
        message = why;
        HasEnded = true;
        return false;
    }

    private ConnectionOutcome End(ref string? message)
    {
        HasEnded = true;
        string how = _link.Ending();
        message = message is null ? how : $"{message} ({how})";
        return ConnectionOutcome.Ended;
    }
}
