using System.Collections.Specialized;
using System.Threading;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Simulation;
using URWPGSim2D.Hosting;
using URWPGSim2D.Tournament;
using URWPGSim2D.Tournament.Batch;
using URWPGSim2D.Viewer;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>tournament --live</c>, the projector view: the tournament's matches are played one after
/// another in the live page, in real time (× <c>--speed</c>), while the class watches; each result is
/// recorded as the match ends, exactly as a tournament played off screen records it. The page's
/// viewers may pause, resume and step the match being played; a match is never restarted (its
/// strategies play it once). On an address other machines can reach the page only watches unless
/// it holds the control token printed at start, and the banner names the addresses students open
/// (<see cref="LiveRun.Open"/>).
/// </summary>
internal sealed class LiveTournament : IDisposable
{
    private readonly LiveFeed _feed = new();
    private readonly object _gate = new();
    private readonly CancellationTokenSource _stop = new();
    private readonly double _speed;
    private readonly CliConsole _console;
    private LiveServer? _server;
    private LiveMatch? _player;
    private Thread? _playing;
    private (Match Match, int Cycles)? _pending;
    private Exception? _failure;
    private ScheduledMatch? _current;
    private MatchResult? _result;
    private int _disposed;

    private LiveTournament(double speed, CliConsole console)
    {
        _speed = speed;
        _console = console;
    }

    /// <summary>Starts the page's server and prints its banner; null (one line on stderr) when the port cannot be used.</summary>
    /// <param name="host">The address to listen on (<c>--host</c>).</param>
    /// <param name="port">The port (<c>--port</c>).</param>
    /// <param name="speed">Multiple of real time (<c>--speed</c>).</param>
    /// <param name="console">Where the banner and each match's line go.</param>
    public static LiveTournament? Open(string host, int port, double speed, CliConsole console)
    {
        var live = new LiveTournament(speed, console);
        live._server = LiveRun.Open(host, port, live._feed, live.Control, null, console, url => console.Out.WriteLine($"live view: {url} (the matches play there one after another)"), "pause, resume and step the matches");
        if (live._server is null)
        {
            live.Dispose();
            return null;
        }

        return live;
    }

    /// <summary>
    /// Plays <paramref name="match"/> in the page (after the one before it) and gives its result once
    /// it is over; called by the tournament's runner, one match at a time.
    /// </summary>
    /// <param name="match">The scheduled match.</param>
    /// <param name="settings">Its settings, with its entrants' fresh strategies.</param>
    public MatchResult Play(ScheduledMatch match, MatchSettings settings)
    {
        var built = (TournamentMatchPlayer.Build(settings), settings.Cycles); // a match that cannot be built (or whose remote client does not come) fails here, on the tournament's thread
        LiveMatch? player;
        lock (_gate)
        {
            _pending = built;
            _current = match;
            _result = null;
            player = _player;
        }

        if (player is null)
        {
            player = new LiveMatch(Build, _speed, paused: false, _feed) { Ended = Over };
            lock (_gate)
            {
                _player = player;
            }

            _playing = new Thread(() => Run(player)) { IsBackground = true, Name = "live tournament" };
            _playing.Start();
        }
        else
        {
            player.Start();
        }

        MatchResult result;
        lock (_gate)
        {
            while (_result is null && _failure is null)
            {
                Monitor.Wait(_gate);
            }

            result = _result ?? throw new InvalidOperationException("the live page's match failed: " + _failure!.Message, _failure);
        }

        _console.Out.Write(string.Create(CultureInfo.InvariantCulture, $"live: match {match.Index} (seed {match.Seed}) over: {string.Join(':', result.Scores ?? [result.Goals0, result.Goals1])}\n"));
        _console.Out.Flush();
        return result;
    }

    /// <summary>Stops the match and the page's server.</summary>
    public void Dispose()
    {
        if (Interlocked.Exchange(ref _disposed, 1) != 0)
        {
            return;
        }

        _stop.Cancel();
        _playing?.Join();
        if (_player is { } player)
        {
            MatchLoop.StopStrategies(player.Match);
        }

        _server?.Stop();
        _server?.Dispose();
        _stop.Dispose();
    }

    // The match to play now, built by Play (the player asks at the first match and at every start).
    private (Match Match, int Cycles) Build()
    {
        lock (_gate)
        {
            return _pending ?? throw new InvalidOperationException("no match to play");
        }
    }

    // The player's thread: a failure of the match being played ends the wait of Play (the tournament records it) instead of the process.
    private void Run(LiveMatch player)
    {
        try
        {
            player.Run(_stop.Token);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            lock (_gate)
            {
                _failure = e;
                Monitor.PulseAll(_gate);
            }
        }
    }

    // On the player's thread when a match is over: its result, read before the next start disposes it.
    private void Over(Match ended)
    {
        try
        {
            MatchLoop.StopStrategies(ended); // told the end now: a remote entrant's client that plays a series goes on to its next match
        }
        catch (TeamFaultException)
        {
            // the result stands; the strategy's end is no part of it
        }

        lock (_gate)
        {
            if (_current is { } match && _result is null)
            {
                _result = MatchResult.Of(match.Index, match.Seed, ended);
                Monitor.PulseAll(_gate);
            }
        }
    }

    private LiveReply Control(string action, NameValueCollection query)
    {
        LiveMatch? player;
        lock (_gate)
        {
            player = _player;
        }

        if (action is "pause" or "resume" or "step")
        {
            player?.Control(action);
            return LiveReply.Done;
        }

        return LiveReply.Refused($"{Engine.Messages.MessageText.Quote(action)}: a tournament's matches are played once each, in turn (pause, resume or step)");
    }
}
