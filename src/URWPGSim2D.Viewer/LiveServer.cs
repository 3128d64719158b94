using System.IO;
using System.Net;
using System.Threading;
using System.Threading.Tasks;

namespace URWPGSim2D.Viewer;

/// <summary>
/// The live view's web server (<see cref="HttpListener"/>, part of .NET): <c>GET /</c> is the
/// viewer page, <c>GET /events</c> the match as Server-Sent Events (a <c>reset</c> event, then
/// every message of the <see cref="LiveFeed"/> from the start, then each new one as it comes),
/// <c>POST /control?action=pause|resume|step|restart</c> drives the match (with a control board also
/// <c>start</c> and <c>recompile</c>, their settings in the query), <c>GET /board</c> is the control
/// board's choices (JSON; 404 without a board) and <c>GET /replay.html</c> the replay page of what has
/// been played. Each viewer connection is served by its own task reading the feed at its own pace.
/// With a control token (a server that others can reach), <c>POST /control</c> needs it as the query's
/// <c>token</c> (403 without it: those viewers only watch), and <c>GET /access</c> tells a page whether
/// its token controls (<c>{"control":true|false}</c>).
/// </summary>
public sealed class LiveServer : IDisposable
{
    private static readonly byte[] ResetMessage = "event: reset\ndata: {}\n\n"u8.ToArray();
    private static readonly byte[] KeepAlive = ": keep-alive\n\n"u8.ToArray();
    private static readonly TimeSpan KeepAliveEvery = TimeSpan.FromSeconds(10);

    private readonly HttpListener _listener = new();
    private readonly LiveFeed _feed;
    private readonly Func<string, System.Collections.Specialized.NameValueCollection, LiveReply> _control;
    private readonly Func<string>? _board;
    private readonly byte[]? _controlToken;
    private readonly byte[] _page;
    private readonly CancellationTokenSource _stop = new();
    private readonly List<Task> _clients = [];
    private Task? _accept;
    private bool _started;

    /// <summary>Creates the server (not yet listening).</summary>
    /// <param name="host">Address to listen on: an IP address or host name; <c>*</c>, <c>+</c> or <c>0.0.0.0</c> for every interface.</param>
    /// <param name="port">TCP port, 1..65535.</param>
    /// <param name="feed">The messages to stream.</param>
    /// <param name="control">Applies a control action with the request's query; its answer is the response.</param>
    /// <param name="board">The control board's choices as JSON (asked at every <c>GET /board</c>), or null for a live view without a board.</param>
    /// <param name="controlToken">The token a viewer must send to control the match, or null when every viewer may (a loopback server).</param>
    public LiveServer(string host, int port, LiveFeed feed, Func<string, System.Collections.Specialized.NameValueCollection, LiveReply> control, Func<string>? board = null, string? controlToken = null)
    {
        _feed = feed;
        _control = control;
        _board = board;
        _controlToken = controlToken is null ? null : Encoding.UTF8.GetBytes(controlToken);
        _page = Encoding.UTF8.GetBytes(ReplayPage.Live(board is not null));
        bool any = host is "*" or "+" or "0.0.0.0";
        string name = host.Contains(':', StringComparison.Ordinal) ? $"[{host}]" : host;
        _listener.Prefixes.Add($"http://{(any ? "+" : name)}:{port}/");
        Url = $"http://{(any ? "0.0.0.0" : name)}:{port}/";
    }

    /// <summary>The address viewers open.</summary>
    public string Url { get; }

    /// <summary>Viewer connections currently streaming.</summary>
    public int Viewers => Volatile.Read(ref _viewers);

    private int _viewers;

    /// <summary>Starts listening.</summary>
    /// <exception cref="LiveServerException">The address cannot be used (port in use, no such address, not allowed).</exception>
    public void Start()
    {
        try
        {
            _listener.Start();
        }
        catch (Exception e) when (e is HttpListenerException or System.Net.Sockets.SocketException or ArgumentException or InvalidOperationException)
        {
            throw new LiveServerException($"cannot listen on {Url} ({e.Message})");
        }

        _started = true;
        _accept = Task.Run(AcceptLoop);
    }

    /// <summary>Stops listening and ends every viewer connection (waits at most a few seconds for them).</summary>
    public void Stop()
    {
        if (_stop.IsCancellationRequested)
        {
            return;
        }

        _stop.Cancel();
        if (!_started)
        {
            return;
        }

        try
        {
            _listener.Stop();
        }
        catch (Exception e) when (e is ObjectDisposedException or HttpListenerException)
        {
            // Already closed.
        }

        Task[] pending;
        lock (_clients)
        {
            pending = [.. _clients];
        }

        try
        {
            Task.WaitAll(pending, TimeSpan.FromSeconds(3));
            _accept?.Wait(TimeSpan.FromSeconds(3));
        }
        catch (AggregateException)
        {
            // A connection that failed while closing is already gone.
        }
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        Stop();
        try
        {
            _listener.Close();
        }
        catch (Exception e) when (e is ObjectDisposedException or HttpListenerException)
        {
            // A listener that never started has nothing to close.
        }

        _stop.Dispose();
    }

    private async Task AcceptLoop()
    {
        while (!_stop.IsCancellationRequested)
        {
            HttpListenerContext context;
            try
            {
                context = await _listener.GetContextAsync().ConfigureAwait(false);
            }
            catch (Exception e) when (e is HttpListenerException or ObjectDisposedException or InvalidOperationException)
            {
                return;
            }

            var task = Task.Run(() => Handle(context));
            lock (_clients)
            {
                _clients.RemoveAll(t => t.IsCompleted);
                _clients.Add(task);
            }
        }
    }

    private async Task Handle(HttpListenerContext context)
    {
        var request = context.Request;
        var response = context.Response;
        try
        {
            string path = request.Url?.AbsolutePath ?? "/";
            switch (request.HttpMethod, path)
            {
                case ("GET", "/" or "/index.html"):
                    await Send(response, 200, "text/html; charset=utf-8", _page).ConfigureAwait(false);
                    break;
                case ("GET", "/events"):
                    await Stream(response).ConfigureAwait(false);
                    break;
                case ("POST", "/control") when !MayControl(request):
                    await Send(response, 403, "text/plain; charset=utf-8", "view only: controlling this match needs the control token the server printed when it started"u8.ToArray()).ConfigureAwait(false);
                    break;
                case ("POST", "/control"):
                    var query = new System.Collections.Specialized.NameValueCollection(request.QueryString);
                    query.Remove("token");
                    var reply = _control(query["action"] ?? string.Empty, query);
                    await Send(response, reply.Status, "text/plain; charset=utf-8", Encoding.UTF8.GetBytes(reply.Text)).ConfigureAwait(false);
                    break;
                case ("GET", "/access"):
                    await Send(response, 200, "application/json; charset=utf-8", MayControl(request) ? "{\"control\":true}"u8.ToArray() : "{\"control\":false}"u8.ToArray()).ConfigureAwait(false);
                    break;
                case ("GET", "/board") when _board is not null:
                    await Send(response, 200, "application/json; charset=utf-8", Encoding.UTF8.GetBytes(_board())).ConfigureAwait(false);
                    break;
                case ("GET", "/replay.html"):
                    if (LiveReplay.Build(_feed) is { } replay)
                    {
                        response.Headers["Content-Disposition"] = $"attachment; filename=\"{LiveReplay.FileName(replay.LastCycle)}\"";
                        await Send(response, 200, "text/html; charset=utf-8", Encoding.UTF8.GetBytes(replay.Page)).ConfigureAwait(false);
                    }
                    else
                    {
                        await Send(response, 404, "text/plain", "nothing played yet"u8.ToArray()).ConfigureAwait(false);
                    }

                    break;
                case ("GET", "/favicon.ico"):
                    await Send(response, 204, "text/plain", []).ConfigureAwait(false);
                    break;
                default:
                    await Send(response, 404, "text/plain", "not found"u8.ToArray()).ConfigureAwait(false);
                    break;
            }
        }
        catch (Exception e) when (e is IOException or HttpListenerException or ObjectDisposedException or OperationCanceledException or InvalidOperationException)
        {
            // The viewer went away or the server is stopping: nothing to do for this connection.
        }
        finally
        {
            try
            {
                response.Abort();
            }
            catch (ObjectDisposedException)
            {
            }
        }
    }

    // Every viewer of a server without a token; else one whose query carries the token (compared in constant time).
    private bool MayControl(HttpListenerRequest request) =>
        _controlToken is null
        || (request.QueryString["token"] is { } given
            && System.Security.Cryptography.CryptographicOperations.FixedTimeEquals(Encoding.UTF8.GetBytes(given), _controlToken));

    private static async Task Send(HttpListenerResponse response, int status, string type, byte[] body)
    {
        response.StatusCode = status;
        response.ContentType = type;
        response.Headers["Cache-Control"] = "no-store";
        response.ContentLength64 = body.Length;
        await response.OutputStream.WriteAsync(body).ConfigureAwait(false);
        response.Close();
    }

    // One viewer's event stream: everything of the current generation, then each new message.
    private async Task Stream(HttpListenerResponse response)
    {
        response.StatusCode = 200;
        response.ContentType = "text/event-stream; charset=utf-8";
        response.Headers["Cache-Control"] = "no-store";
        response.SendChunked = true;
        var output = response.OutputStream;
        var stop = _stop.Token;
        var batch = new List<byte[]>(512);
        int generation = -1, next = 0;
        Interlocked.Increment(ref _viewers);
        try
        {
            while (!stop.IsCancellationRequested)
            {
                Task changed = _feed.Changed;
                int current = _feed.Read(generation, ref next, batch, 512);
                if (current != generation)
                {
                    generation = current;
                    await output.WriteAsync(ResetMessage, stop).ConfigureAwait(false);
                }

                foreach (var message in batch)
                {
                    await output.WriteAsync(message, stop).ConfigureAwait(false);
                }

                await output.FlushAsync(stop).ConfigureAwait(false);
                bool wrote = batch.Count > 0;
                batch.Clear();
                if (wrote)
                {
                    continue;
                }

                if (await Task.WhenAny(changed, Task.Delay(KeepAliveEvery, stop)).ConfigureAwait(false) != changed)
                {
                    stop.ThrowIfCancellationRequested();
                    await output.WriteAsync(KeepAlive, stop).ConfigureAwait(false);
                }
            }
        }
        finally
        {
            Interlocked.Decrement(ref _viewers);
        }
    }
}
