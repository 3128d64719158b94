using System.Net;
using System.Net.Sockets;
using URWPGSim2D.Protocol;

namespace URWPGSim2D.Hosting;

/// <summary>
/// A team played by a remote client (<c>--strategy TEAM=remote:PORT</c>): the listening socket,
/// bound when the options are read, the token a client must present and how long the match waits
/// for one. Every match of the run opens a <see cref="RemoteStrategy"/> on it. Refused clients and
/// bad answers are logged, one line each, up to <see cref="MaximumLogLines"/>.
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
    private int _logged;

    /// <summary>Binds the seat's socket.</summary>
    /// <param name="team">The team, 0 or 1.</param>
    /// <param name="address">The address to listen on.</param>
    /// <param name="port">The port; 0 takes a free one (see <see cref="EndPoint"/>).</param>
    /// <param name="token">The token a client must present, or null for none.</param>
    /// <param name="wait">How long a match waits for the client before it starts.</param>
    /// <param name="log">Where the seat's lines go (the server's standard error).</param>
    /// <exception cref="StrategyLoadException">The address and port cannot be listened on.</exception>
    public RemoteSeat(int team, IPAddress address, int port, string? token, TimeSpan wait, Action<string> log)
    {
        ArgumentNullException.ThrowIfNull(address);
        ArgumentNullException.ThrowIfNull(log);
        Team = team;
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

    /// <summary>The team the seat plays.</summary>
    public int Team { get; }

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
            _log($"team {Team} (remote): {line}");
        }
        else if (n == MaximumLogLines + 1)
        {
            _log($"team {Team} (remote): more than {MaximumLogLines} lines; no more are logged");
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

    /// <inheritdoc/>
    public void Dispose() => _listener.Stop();

    private static string Format(IPEndPoint e) => e.AddressFamily == AddressFamily.InterNetworkV6
        ? $"[{e.Address}]:{e.Port.ToString(CultureInfo.InvariantCulture)}"
        : $"{e.Address}:{e.Port.ToString(CultureInfo.InvariantCulture)}";
}
