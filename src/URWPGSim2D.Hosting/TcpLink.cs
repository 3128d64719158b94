using System.Net.Sockets;

namespace URWPGSim2D.Hosting;

/// <summary>
/// A remote client's TCP connection as a strategy link: Nagle off (every line goes at once), a
/// read past the wait's limit throws <see cref="TimeoutException"/> with the connection intact
/// (the late answer is read and dropped later), and a write that cannot go within
/// <see cref="SendLimit"/> (a client that does not read) breaks the link.
/// </summary>
internal sealed class TcpLink : IStrategyLink
{
    /// <summary>Wall time a write to the client may block before the link is given up.</summary>
    public static readonly TimeSpan SendLimit = TimeSpan.FromSeconds(10);

    private readonly Socket _socket;
    private readonly WaitingStream _stream;
    private bool _closedByServer;

    /// <summary>Takes over an accepted socket.</summary>
    public TcpLink(Socket socket)
    {
        ArgumentNullException.ThrowIfNull(socket);
        _socket = socket;
        _socket.NoDelay = true;
        _socket.SendTimeout = (int)SendLimit.TotalMilliseconds;
        Peer = socket.RemoteEndPoint?.ToString() ?? "?";
        _stream = new WaitingStream(socket);
    }

    /// <summary>The client's address and port.</summary>
    public string Peer { get; }

    /// <inheritdoc/>
    public Stream FromClient => _stream;

    /// <inheritdoc/>
    public Stream ToClient => _stream;

    /// <inheritdoc/>
    public bool SurvivesLateAnswer => true;

    /// <summary>False: a wait that runs out leaves the connection open (<see cref="SurvivesLateAnswer"/>).</summary>
    public bool CutByWait => false;

    /// <summary>Null: a remote client's CPU time is not measured.</summary>
    /// <returns>Null.</returns>
    public TimeSpan? CpuTime() => null;

    /// <summary>Null: a remote client's waits are not measured.</summary>
    /// <returns>Null.</returns>
    public TimeSpan? WaitingTime() => null;

    /// <inheritdoc/>
    public long? PeakMemoryBytes() => null;

    /// <inheritdoc/>
    public void BeginWait(TimeSpan limit) => _stream.Deadline = Stopwatch.GetTimestamp() + (long)(limit.TotalSeconds * Stopwatch.Frequency);

    /// <inheritdoc/>
    public void EndWait() => _stream.Deadline = long.MaxValue;

    /// <inheritdoc/>
    public void Abort()
    {
        _closedByServer = true;
        _socket.Close(0);
    }

    /// <inheritdoc/>
    public void Finish(int ms)
    {
        try
        {
            _socket.Shutdown(SocketShutdown.Send);
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
            // it has gone already
        }

        _closedByServer = true;
        _socket.Close(ms / 1000);
    }

    /// <summary>
    /// Closes a connection kept between matches without a reset: says the server sends no more, reads what the
    /// client still sends (its hello for a next match) for up to a second, then closes, so the client reads the
    /// end of the stream.
    /// </summary>
    public void Close()
    {
        try
        {
            _socket.Shutdown(SocketShutdown.Send);
            var drain = new byte[4096];
            var until = Stopwatch.GetTimestamp() + Stopwatch.Frequency;
            while (Stopwatch.GetTimestamp() < until && _socket.Poll(100_000, SelectMode.SelectRead) && _socket.Receive(drain) > 0)
            {
            }
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
            // it has gone already
        }

        _closedByServer = true;
        _socket.Dispose();
    }

    /// <inheritdoc/>
    public string Ending() => _closedByServer ? $"the server closed the connection to {Peer}" : $"the client at {Peer} disconnected";

    /// <inheritdoc/>
    public void Dispose() => _socket.Dispose();

    // The socket as a stream whose reads wait for data only until a deadline (Socket.Poll), so a
    // late answer leaves the stream and the framing above it as they were.
    private sealed class WaitingStream(Socket socket) : Stream
    {
        public long Deadline { get; set; } = long.MaxValue;

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => true;

        public override long Length => throw new NotSupportedException();

        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }

        public override int Read(byte[] buffer, int offset, int count) => Read(buffer.AsSpan(offset, count));

        public override int Read(Span<byte> buffer)
        {
            if (Deadline != long.MaxValue)
            {
                long left = Deadline - Stopwatch.GetTimestamp();
                int micros = left <= 0 ? 0 : (int)Math.Min(left * 1_000_000.0 / Stopwatch.Frequency, int.MaxValue);
                if (!socket.Poll(micros, SelectMode.SelectRead))
                {
                    throw new TimeoutException("no answer within the deadline");
                }
            }

            try
            {
                return socket.Receive(buffer);
            }
            catch (SocketException e) when (e.SocketErrorCode is SocketError.ConnectionReset or SocketError.ConnectionAborted or SocketError.Shutdown)
            {
                return 0; // the client reset the connection: it has gone
            }
            catch (ObjectDisposedException)
            {
                return 0; // the server cut it
            }
        }

        public override void Write(byte[] buffer, int offset, int count) => Write(buffer.AsSpan(offset, count));

        public override void Write(ReadOnlySpan<byte> buffer)
        {
            try
            {
                while (!buffer.IsEmpty)
                {
                    buffer = buffer[socket.Send(buffer)..];
                }
            }
            catch (SocketException e)
            {
                throw new IOException("the connection broke: " + e.Message, e);
            }
            catch (ObjectDisposedException e)
            {
                throw new IOException("the connection was closed", e);
            }
        }

        public override void Flush()
        {
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();
    }
}
