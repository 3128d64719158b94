using URWPGSim2D.Protocol;

namespace URWPGSim2D.Hosting;

/// <summary>
/// A remote team's strategy for one match: a <see cref="StrategyConnection"/> over the TCP
/// connection of the client that took the <see cref="RemoteSeat"/>. The server waits for each
/// answer up to the team's deadline in wall time (the first answer of a connection, when the
/// client's code is compiled, up to the hang limit a strategy in the server's process has), then
/// charges a time-out exactly as for a local strategy. A client that disconnects or is cut off is
/// charged once and its fish stop; a client may connect again (with the same token) at any later
/// cycle and plays on from there. A client that plays a series (<see cref="HelloMessage.Series"/>)
/// is kept on the seat after the match's <c>end</c>, and the seat's next match takes it first.
/// </summary>
internal sealed class RemoteStrategy : IConnectedStrategy
{
    // Clients taken at most in one cycle while the team has none (each gets HelloLimit for its hello).
    private const int AcceptsPerCycle = 2;

    private readonly RemoteSeat _seat;
    private readonly AssignmentMessage _assignment;
    private StrategyConnection? _current;
    private string? _lastName;

    /// <summary>Creates the match's side of the seat; no client yet (<see cref="WaitForClient"/>).</summary>
    public RemoteStrategy(RemoteSeat seat, AssignmentMessage assignment)
    {
        ArgumentNullException.ThrowIfNull(seat);
        ArgumentNullException.ThrowIfNull(assignment);
        _seat = seat;
        _assignment = assignment;
    }

    /// <summary>
    /// The name the connected client sent in its hello; after it disconnected or the match ended,
    /// the name of the last client that connected (so the summary names the team as it played).
    /// </summary>
    public string? TeamName => _current?.TeamName ?? _lastName;

    /// <inheritdoc/>
    public string? EndedBy { get; private set; }

    /// <summary>True: after a disconnect another client may take the team over.</summary>
    public bool Reconnects => true;

    /// <summary>Whether the connected client plays a series (it is told the end and kept, even after its team ran out of time).</summary>
    public bool Series => _current?.Series == true;

    /// <summary>Whether a client is connected.</summary>
    public bool Connected => _current is not null;

    /// <summary>
    /// Says on which address the seat waits for its client: called for every remote team before any
    /// waits (<see cref="WaitForClient"/>), so that each team's address is known before the first client connects.
    /// Nothing is said when a kept client waits for this match or the seat said it already since its last client came.
    /// </summary>
    public void Announce() => _seat.Announce();

    /// <summary>
    /// Waits up to the seat's wait for a client that says a good hello; refused ones are logged and
    /// the wait goes on. The address is said first (<see cref="Announce"/>) unless <paramref name="announced"/>.
    /// </summary>
    /// <param name="announced">Whether <see cref="Announce"/> was called already.</param>
    /// <exception cref="RemoteWaitException">None came in time.</exception>
    public void WaitForClient(bool announced = false)
    {
        if (!announced)
        {
            Announce();
        }

        var clock = Stopwatch.StartNew();
        while (_current is null)
        {
            TimeSpan left = _seat.Wait - clock.Elapsed;
            if (left <= TimeSpan.Zero)
            {
                throw new RemoteWaitException($"{_seat.Option}: no client connected to {_seat.Address} within {_seat.Wait.TotalSeconds:0.#} s (--remote-wait)", _assignment.Team);
            }

            if (!TryKept())
            {
                _seat.Announce(); // the kept client has gone: a new one is waited for
                TryAccept(left);
            }
        }
    }

    /// <inheritdoc/>
    public TimeSpan? CpuTime() => null;

    /// <inheritdoc/>
    public TimeSpan? WaitingTime() => null;

    /// <inheritdoc/>
    public long? PeakMemoryBytes() => null;

    /// <inheritdoc/>
    public DebugRecorder? Drawings => _current?.Drawings;

    /// <inheritdoc/>
    public StrategyLog? Log => _current?.Log;

    /// <inheritdoc/>
    public ConnectionOutcome Decide(MatchSnapshot snapshot, Span<Decision> decisions, TimeSpan waitLimit, out string? message)
    {
        message = null;
        EndedBy = null;
        for (int i = 0; i < AcceptsPerCycle && _current is null; i++)
        {
            if (!TryKept() && !TryAccept(TimeSpan.Zero))
            {
                break;
            }
        }

        if (_current is not { } connection)
        {
            return ConnectionOutcome.Absent;
        }

        var outcome = connection.Decide(snapshot, decisions, waitLimit, out message);
        if (!connection.HasEnded)
        {
            return outcome;
        }

        EndedBy = connection.EndedBy;
        _seat.Log($"cycle {snapshot.Cycle + 1}: {EndedBy ?? message}; waiting for the client to connect again on {_seat.Address}");
        _seat.WaitingSaid = true;
        connection.Dispose();
        _current = null;
        return outcome == ConnectionOutcome.Ended ? ConnectionOutcome.Disconnected : outcome;
    }

    /// <inheritdoc/>
    public void Stop(EndMessage end)
    {
        if (_current is { } connection && connection.KeepFor(end))
        {
            _seat.Keep((TcpLink)connection.Link, connection.Channel); // its next match takes it
        }
        else
        {
            _current?.Stop(end);
        }

        _current = null;
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        _current?.Dispose();
        _current = null;
    }

    // Takes the client kept from the seat's last match, if there is one and it says hello again; false otherwise (it has gone).
    private bool TryKept()
    {
        if (_seat.TakeKept() is not { } kept)
        {
            return false;
        }

        var connection = Connect(kept.Link, kept.Channel);
        if (!connection.Handshake(out _))
        {
            connection.Dispose();
            return false;
        }

        Take(connection, "plays on");
        return true;
    }

    // Takes one client that connects within the time, if it says a good hello.
    private bool TryAccept(TimeSpan within)
    {
        var socket = _seat.Accept(within);
        if (socket is null)
        {
            return false;
        }

        var link = new TcpLink(socket);
        var connection = Connect(link, null);
        if (!connection.Handshake(out _))
        {
            connection.Dispose();
            return true; // refused (and logged); the caller may take the next
        }

        Take(connection, "connected from " + link.Peer);
        return true;
    }

    private StrategyConnection Connect(TcpLink link, LineChannel? channel)
    {
        var deadline = TimeSpan.FromMilliseconds(_assignment.DeadlineMs);
        return new StrategyConnection(link, _assignment, deadline, RemoteSeat.HelloLimit, _seat.Token, line => _seat.Log($"{link.Peer}: {line}"), channel: channel)
        {
            FirstAnswerLimit = ThreadTimeClock.HangLimitFor(deadline),
            OffersSeries = true,
        };
    }

    private void Take(StrategyConnection connection, string how)
    {
        if (connection.Continued)
        {
            // A series client's next match: said once, when its name changed.
            if (connection.TeamName != _seat.ClientName)
            {
                _seat.Log($"client {(connection.TeamName is { } next ? MessageTextOf(next) + " " : "")}{how}");
            }
        }
        else
        {
            _seat.Log($"client {(connection.TeamName is { } name ? MessageTextOf(name) + " " : "")}{how}");
        }

        _current = connection;
        _lastName = connection.TeamName ?? _lastName;
        _seat.ClientName = _lastName;
        _seat.WaitingSaid = false;
    }

    private static string MessageTextOf(string name) => Engine.Messages.MessageText.Quote(name);
}
