using URWPGSim2D.Protocol;

namespace URWPGSim2D.Hosting;

/// <summary>
/// The client side of the strategy protocol (docs/protocol.md): says hello, takes the assignment,
/// then answers every cycle with the strategy's decisions until the server's end. The strategy is
/// called on the thread that reads the cycle, and every call is answered when it returns, however
/// long it takes: the server measures the time and takes a late call's overrun from the team's time
/// bank (<see cref="TimeBank"/>), so the client never gives a call up and needs no thread of its own
/// for it (a cycle passes no thread hand-over inside the client). An exception or a contract
/// violation is answered as that cycle's fault, and the decisions in force stay as they were. A
/// strategy host runs this over its standard input and output. <see cref="PlaySeries"/> plays every
/// match a server gives one connection (a remote entrant of a tournament).
/// </summary>
public sealed class StrategyClient
{
    private readonly LineChannel _channel;
    private readonly MessageWriter _writer = new();

    /// <summary>Creates a client over the streams from and to the server.</summary>
    public StrategyClient(Stream fromServer, Stream toServer)
    {
        _channel = new LineChannel(fromServer, toServer, ProtocolLimits.ServerLineBytes);
    }

    /// <summary>How a connection ended.</summary>
    public enum Ending
    {
        /// <summary>The server sent <c>end</c>.</summary>
        Ended,

        /// <summary>The server refused the hello (<c>error</c>).</summary>
        Refused,

        /// <summary>The server closed the connection before <c>end</c>.</summary>
        Closed,
    }

    /// <summary>The server's <c>end</c> (after <see cref="Ending.Ended"/>), or null.</summary>
    public EndMessage? End { get; private set; }

    /// <summary>The server's <c>error</c> message (after <see cref="Ending.Refused"/>), or null.</summary>
    public string? Error { get; private set; }

    /// <summary>Plays one connection with <paramref name="strategy"/>.</summary>
    /// <exception cref="ProtocolException">The server broke the protocol.</exception>
    public Ending Play(IStrategy strategy, string? token)
    {
        ArgumentNullException.ThrowIfNull(strategy);
        _channel.WriteLine(_writer.Hello(ProtocolVersion.Current, token, NameOf(strategy), packed: true));
        return Match(_ => strategy, out _);
    }

    /// <summary>
    /// Plays every match the server gives the connection (<c>"series":true</c> in the hello, docs/protocol.md): after
    /// each <c>end</c> (told to <paramref name="ended"/>) it says hello again and waits for the next assignment, with a
    /// fresh strategy from <paramref name="strategies"/> (given the one before, or null for the first match). A server
    /// that closes the connection after an <c>end</c> has no more matches: that is <see cref="Ending.Ended"/>.
    /// </summary>
    /// <param name="first">The first match's strategy (its name goes in every hello).</param>
    /// <param name="strategies">The strategy of each later match, given the one before.</param>
    /// <param name="token">The token the server asks for, or null.</param>
    /// <param name="ended">Told each match's <c>end</c>.</param>
    /// <exception cref="ProtocolException">The server broke the protocol.</exception>
    public Ending PlaySeries(IStrategy first, Func<IStrategy, IStrategy> strategies, string? token, Action<EndMessage>? ended = null)
    {
        ArgumentNullException.ThrowIfNull(first);
        ArgumentNullException.ThrowIfNull(strategies);
        string? name = NameOf(first);
        var strategy = first;
        bool played = false;
        while (true)
        {
            Ending ending;
            bool more;
            try
            {
                _waiting = true;
                _channel.WriteLine(_writer.Hello(ProtocolVersion.Current, token, name, packed: true, series: true));
                ending = Match(assignment => played ? strategy = strategies(strategy) : strategy, out more);
            }
            catch (IOException) when (played && _waiting)
            {
                return Ending.Ended; // the server closed the connection after the last end (with a reset)
            }

            if (ending == Ending.Closed && played && _waiting)
            {
                return Ending.Ended; // no next match: the server closed the connection after the last end
            }

            if (ending != Ending.Ended)
            {
                return ending;
            }

            played = true;
            ended?.Invoke(End!);
            if (!more)
            {
                return Ending.Ended; // the server did not offer a next match
            }
        }
    }

    private bool _waiting; // no assignment read yet since the last hello

    private static string? NameOf(IStrategy strategy)
    {
        try
        {
            return strategy.TeamName;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return null; // the name is for display only
        }
    }

    // One match after a hello: the assignment, then every cycle until the end; more: the server keeps the connection for another.
    private Ending Match(Func<AssignmentMessage, IStrategy> strategyFor, out bool more)
    {
        more = false;
        _waiting = true;
        if (!_channel.TryReadLine(out var line))
        {
            return Ending.Closed;
        }

        _waiting = false;

        switch (MessageReader.TypeOf(line))
        {
            case MessageType.Assignment:
                break;
            case MessageType.Error:
                Error = MessageReader.ReadError(line);
                return Ending.Refused;
            default:
                throw new ProtocolException("expected an assignment after hello");
        }

        var assignment = MessageReader.ReadAssignment(line);
        var strategy = strategyFor(assignment);
        var reader = new CycleReader(assignment);
        var drawings = assignment.Draw ? new DebugRecorder() : null;
        StrategyLog? log = null;
        if (assignment.Log)
        {
            ConsoleRouter.Install(); // this process plays one strategy: its console is the strategy's
            log = new StrategyLog();
        }

        var call = new Call(strategy, assignment.Fish, drawings, log);
        while (_channel.TryReadLine(out line))
        {
            switch (MessageReader.TypeOf(line))
            {
                case MessageType.Cycle:
                    int cycle = reader.Read(line);
                    Answer(call, reader.Snapshot, cycle);
                    break;
                case MessageType.End:
                    End = MessageReader.ReadEnd(line);
                    more = assignment.Series;
                    return Ending.Ended;
                case MessageType.Error:
                    Error = MessageReader.ReadError(line);
                    return Ending.Refused;
                default:
                    break; // a later version's message this client does not need
            }
        }

        return Ending.Closed;
    }

    private static string? LogOf(StrategyLog? log) => log is { Length: > 0 } ? log.Kept : null;

    // One cycle: the strategy decides on this thread, and its answer (decisions or fault) goes back in one write.
    private void Answer(Call call, MatchSnapshot snapshot, int cycle)
    {
        var error = call.Decide(snapshot);
        var log = call.Log;
        switch (error)
        {
            case null:
                _channel.WriteLine(_writer.Decisions(cycle, call.InForce, call.Drawings, LogOf(log), log?.Dropped ?? 0));
                break;
            case StrategyContractException:
                _channel.WriteLine(_writer.Fault(cycle, AnswerKind.BadAnswer, error.Message, call.Drawings, LogOf(log), log?.Dropped ?? 0));
                break;
            default:
                _channel.WriteLine(_writer.Fault(cycle, AnswerKind.Exception, $"{error.GetType().Name}: {error.Message}", call.Drawings, LogOf(log), log?.Dropped ?? 0));
                break;
        }
    }

    // The strategy's calls: its decisions in force, where a call writes, and what it draws and prints.
    private sealed class Call(IStrategy strategy, int[] fish, DebugRecorder? drawings, StrategyLog? log)
    {
        private readonly Decision[] _work = new Decision[fish.Length];

        public Decision[] InForce { get; } = CreateInForce(fish.Length);

        public DebugRecorder? Drawings => drawings;

        public StrategyLog? Log => log;

        // Calls the strategy on this thread; null when it decided (InForce replaced), else what it threw (InForce kept).
        public Exception? Decide(MatchSnapshot snapshot)
        {
            InForce.CopyTo(_work, 0);
            drawings?.Enter(fish);
            if (log is not null)
            {
                log.Clear();
                ConsoleRouter.Enter(log);
            }

            try
            {
                strategy.Decide(snapshot, fish, _work);
            }
            catch (Exception e)
            {
                return e;
            }
            finally
            {
                if (drawings is not null)
                {
                    DebugRecorder.Exit();
                }

                if (log is not null)
                {
                    ConsoleRouter.Exit();
                }
            }

            _work.CopyTo(InForce, 0);
            return null;
        }

        private static Decision[] CreateInForce(int count)
        {
            var decisions = new Decision[count];
            Array.Fill(decisions, Decision.Stop);
            return decisions;
        }
    }
}
