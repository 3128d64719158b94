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
/// strategy host runs this over its standard input and output.
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
        string? name;
        try
        {
            name = strategy.TeamName;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            name = null; // the name is for display only
        }

        _channel.WriteLine(_writer.Hello(ProtocolVersion.Current, token, name, packed: true));
        if (!_channel.TryReadLine(out var line))
        {
            return Ending.Closed;
        }

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
