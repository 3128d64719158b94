using System.Net;
using System.Net.Sockets;
using URWPGSim2D.Protocol;

namespace URWPGSim2D.Hosting;

/// <summary>
/// A team played by a remote client (<c>--strategy TEAM=remote:PORT</c>): the listening socket,
/// bound when the options are read, the token a client must present and how long the match waits
/// for one. Every match of the run opens a <see cref="RemoteStrategy"/> on it. Refused clients and
/// bad answers are logged, one line each, up to <see cref="MaximumLogLines"/>. A client that plays a
/// series (<see cref="HelloMessage.Series"/>) is kept between matches: the next match the seat plays
/// takes it first. A seat plays one match at a time.
/// </summary>
public sealed class RemoteSeat : IDisposable
{
    /// <summary>Default <c>--remote-wait</c>, seconds.</summary>
    public const int DefaultWaitSeconds = 60;

    /// <summary>Lines a seat logs at most; after them one line says that no more follow.</summary>
    public const int MaximumLogLines = 50;

    /// <summary>Wall time a client has from its connection to its hello.</summary>
    public static readonly TimeSpan HelloLimit = TimeSpan.FromSeconds(5);

    private readonly TcpListener _listener;
    private readonly Action<string> _log;
    private readonly object _gate = new();
    private int _logged;
    private (TcpLink Link, LineChannel Channel)? _kept;

    /// <summary>Binds the seat's socket.</summary>
    /// <param name="team">The team, 0 or 1.</param>
    /// <param name="address">The address to listen on.</param>
    /// <param name="port">The port; 0 takes a free one (see <see cref="EndPoint"/>).</param>
    /// <param name="token">The token a client must present, or null for none.</param>
    /// <param name="wait">How long a match waits for the client before it starts.</param>
    /// <param name="log">Where the seat's lines go (the server's standard error).</param>
    /// <exception cref="StrategyLoadException">The address and port cannot be listened on.</exception>
    public RemoteSeat(int team, IPAddress address, int port, string? token, TimeSpan wait, Action<string> log)
        : this($"team {team.ToString(CultureInfo.InvariantCulture)}", $"--strategy {team.ToString(CultureInfo.InvariantCulture)}=remote", address, port, token, wait, log)
    {
        Team = team;
    }

    /// <summary>Binds the seat's socket for a seat named <paramref name="who"/> (a tournament's entrant).</summary>
    /// <param name="who">What its lines call the seat (<c>entrant NAME</c>): each line starts with it and <c> (remote): </c>.</param>
    /// <param name="option">What the line that says no client came starts with (<c>--entrant NAME=remote</c>).</param>
    /// <param name="address">The address to listen on.</param>
    /// <param name="port">The port; 0 takes a free one (see <see cref="EndPoint"/>).</param>
    /// <param name="token">The token a client must present, or null for none.</param>
    /// <param name="wait">How long a match waits for the client before it starts.</param>
    /// <param name="log">Where the seat's lines go (the server's standard error).</param>
    /// <exception cref="StrategyLoadException">The address and port cannot be listened on.</exception>
    public RemoteSeat(string who, string option, IPAddress address, int port, string? token, TimeSpan wait, Action<string> log)
    {
        ArgumentNullException.ThrowIfNull(who);
        ArgumentNullException.ThrowIfNull(option);
        ArgumentNullException.ThrowIfNull(address);
        ArgumentNullException.ThrowIfNull(log);
        Who = who;
        Option = option;
        Token = token;
        Wait = wait;
        _log = log;
        _listener = new TcpListener(address, port);
        try
        {
            _listener.Start(backlog: 4);
        }
        catch (SocketException e)
        {
            throw new StrategyLoadException($"cannot listen on {Format(new IPEndPoint(address, port))}: {e.Message}");
        }

        EndPoint = (IPEndPoint)_listener.LocalEndpoint;
    }

    /// <summary>The team the seat plays (<c>run</c>); 0 for a tournament's entrant, whose team changes from match to match.</summary>
    public int Team { get; }

    /// <summary>What the seat's lines call it: <c>team 1</c>, <c>entrant NAME</c>.</summary>
    public string Who { get; }

    /// <summary>What the line that says no client came starts with: <c>--strategy 1=remote</c>, <c>--entrant NAME=remote</c>.</summary>
    public string Option { get; }

    /// <summary>The name the last client that connected sent in its hello, or null.</summary>
    public string? ClientName { get; internal set; }

    /// <summary>Whether the seat has said it waits for a client since its last client connected (so a next match does not say it again).</summary>
    internal bool WaitingSaid { get; set; }

    /// <summary>Whether a client that plays a series waits on the seat for its next match.</summary>
    public bool HasKept
    {
        get
        {
            lock (_gate)
            {
                return _kept is not null;
            }
        }
    }

    /// <summary>The token a client must present, or null.</summary>
    public string? Token { get; }

    /// <summary>How long a match waits for its client.</summary>
    public TimeSpan Wait { get; }

    /// <summary>The address and port the seat listens on (the real port when 0 was asked).</summary>
    public IPEndPoint EndPoint { get; }

    /// <summary>The seat's address as a client names it: <c>ADDR:PORT</c>, IPv6 in brackets.</summary>
    public string Address => Format(EndPoint);

    /// <summary>A remote strategy for one match on this seat.</summary>
    internal RemoteStrategy Open(AssignmentMessage assignment) => new(this, assignment);

    /// <summary>Logs one line about this seat (counted against <see cref="MaximumLogLines"/>).</summary>
    public void Log(string line)
    {
        int n = Interlocked.Increment(ref _logged);
        if (n <= MaximumLogLines)
        {
            _log($"{Who} (remote): {line}");
        }
        else if (n == MaximumLogLines + 1)
        {
            _log($"{Who} (remote): more than {MaximumLogLines} lines; no more are logged");
        }
    }

    /// <summary>Says once on which address the seat waits for a client, unless a kept client waits or it was said since the last client came.</summary>
    public void Announce()
    {
        if (!WaitingSaid && !HasKept)
        {
            WaitingSaid = true;
            Log($"waiting for a client on {Address}");
        }
    }

    /// <summary>Keeps the connection of a client that plays a series for the seat's next match (one that was kept before is closed).</summary>
    internal void Keep(TcpLink link, LineChannel channel)
    {
        (TcpLink Link, LineChannel Channel)? old;
        lock (_gate)
        {
            old = _kept;
            _kept = (link, channel);
        }

        old?.Link.Dispose();
    }

    /// <summary>Takes the kept client's connection, or null.</summary>
    internal (TcpLink Link, LineChannel Channel)? TakeKept()
    {
        lock (_gate)
        {
            var kept = _kept;
            _kept = null;
            return kept;
        }
    }

    /// <summary>Takes the next client that connects within <paramref name="within"/>, or null.</summary>
    public Socket? Accept(TimeSpan within)
    {
        long micros = Math.Max(0, (long)(within.TotalMilliseconds * 1000));
        if (!_listener.Server.Poll((int)Math.Min(micros, int.MaxValue), SelectMode.SelectRead))
        {
            return null;
        }

        return _listener.AcceptSocket();
    }

    /// <summary>Stops listening and closes a kept client's connection (the client reads the end of the stream: no more matches).</summary>
    public void Dispose()
    {
        _listener.Stop();
        TakeKept()?.Link.Close();
    }

    private static string Format(IPEndPoint e) => e.AddressFamily == AddressFamily.InterNetworkV6
        ? $"[{e.Address}]:{e.Port.ToString(CultureInfo.InvariantCulture)}"
        : $"{e.Address}:{e.Port.ToString(CultureInfo.InvariantCulture)}";
}
