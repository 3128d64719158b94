using System;
using System.IO;
using URWPGSim2D.Protocol;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// The client side of the strategy protocol (docs/protocol.md): says hello, takes the assignment,
/// then answers every cycle with the strategy's decisions until the server's end. The strategy runs
/// on its own thread (<see cref="IsolatedStrategyRunner"/>) and every call is answered when it
/// returns, however long it takes: the server measures the time and takes a late call's overrun
/// from the team's time bank (<see cref="TimeBank"/>). An exception or a contract violation is
/// answered as that cycle's fault, and the decisions in force stay as they were. A strategy host
/// runs this over its standard input and output.
/// </summary>
internal sealed class StrategyClient
{
    private readonly LineChannel _channel;
    private readonly MessageWriter _writer = new();
    private readonly Func<StrategyClock> _clock;

    /// <summary>Creates a client over the streams from and to the server.</summary>
    public StrategyClient(Stream fromServer, Stream toServer, Func<StrategyClock>? clock = null)
    {
        _channel = new LineChannel(fromServer, toServer, ProtocolLimits.ServerLineBytes);
        _clock = clock ?? (() => new ThreadTimeClock());
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

        _channel.WriteLine(_writer.Hello(ProtocolVersion.Current, token, name));
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
        var runner = new IsolatedStrategyRunner(strategy, assignment.Fish.Length, assignment.Team, _clock());
        if (assignment.Draw)
        {
            runner.RecordDrawings();
        }

        if (assignment.Log)
        {
            ConsoleRouter.Install(); // this process plays one strategy: its console is the strategy's
            runner.RecordLog();
        }

        var inForce = new Decision[assignment.Fish.Length];
        Array.Fill(inForce, Decision.Stop);
        try
        {
            while (_channel.TryReadLine(out line))
            {
                switch (MessageReader.TypeOf(line))
                {
                    case MessageType.Cycle:
                        int cycle = reader.Read(line);
                        Answer(runner, reader.Snapshot, assignment, cycle, inForce);
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
        finally
        {
            runner.Stop();
        }
    }

    private static string? LogOf(IsolatedStrategyRunner runner) => runner.Log is { Length: > 0 } log ? log.Kept : null;

    private void Answer(IsolatedStrategyRunner runner, MatchSnapshot snapshot, AssignmentMessage assignment, int cycle, Decision[] inForce)
    {
        switch (runner.Decide(snapshot, assignment.Fish, inForce, System.Threading.Timeout.InfiniteTimeSpan, System.Threading.Timeout.InfiniteTimeSpan, out Exception? error, out _, out _))
        {
            case IsolatedStrategyRunner.Outcome.Decided:
                _channel.WriteLine(_writer.Decisions(cycle, inForce, runner.Drawings, LogOf(runner), runner.Log?.Dropped ?? 0));
                break;
            case IsolatedStrategyRunner.Outcome.Threw when error is StrategyContractException:
                _channel.WriteLine(_writer.Fault(cycle, AnswerKind.BadAnswer, error.Message, runner.Drawings, LogOf(runner), runner.Log?.Dropped ?? 0));
                break;
            case IsolatedStrategyRunner.Outcome.Threw:
                _channel.WriteLine(_writer.Fault(cycle, AnswerKind.Exception, $"{error!.GetType().Name}: {error.Message}", runner.Drawings, LogOf(runner), runner.Log?.Dropped ?? 0));
                break;
            default:
                _channel.WriteLine(_writer.Fault(cycle, AnswerKind.Timeout, $"no decision within {assignment.DeadlineMs} ms"));
                break;
        }
    }
}
