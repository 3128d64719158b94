using System.Diagnostics;
using System.Threading;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Simulation;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Viewer;

/// <summary>
/// Plays a match for the live view on its own thread, one cycle every 100 ms / speed (deadline
/// based, so it does not drift), publishing each cycle's trace line and the play status to a
/// <see cref="LiveFeed"/>. Pause, resume, step and restart come from any thread (the viewers'
/// buttons); a step plays exactly one cycle and leaves the match paused. Only the playing thread
/// publishes, so a status message always follows every cycle line it counts. A restart (or a start, which also
/// plays on) builds the next match from what <c>next</c> gives then, so a control board may change
/// the item, its length and the strategies between matches. The cycles are played by
/// the one match loop (<see cref="MatchLoop"/>), so the match ends where <c>run</c> ends it (a tied
/// polo match plays its extra time and penalties live too); then it tells <see cref="Ended"/> and
/// waits (a restart plays it again) until <see cref="Run"/> is cancelled.
/// </summary>
public sealed class LiveMatch : ITraceSink
{
    private static readonly byte[] DataPrefix = "data: "u8.ToArray();
    private static readonly byte[] MessageEnd = "\n\n"u8.ToArray();

    private readonly Func<(Match Match, int Cycles)> _next;
    private readonly LiveFeed _feed;
    private readonly object _gate = new();
    private readonly Stopwatch _busy = new();
    private readonly Stopwatch _played = new();
    private MatchLoop _loop;
    private bool _paused;
    private int _steps;
    private bool _restart;
    private bool _statusChanged;

    /// <summary>Creates the player; the first match is built at once.</summary>
    /// <param name="next">Builds the next match and says how many cycles its regular time lasts (called again on every restart or start, on the playing thread).</param>
    /// <param name="speed">Multiple of real time (1: 100 ms a cycle).</param>
    /// <param name="paused">Whether to wait for resume or step before the first cycle.</param>
    /// <param name="feed">Where cycles and status go.</param>
    public LiveMatch(Func<(Match Match, int Cycles)> next, double speed, bool paused, LiveFeed feed)
    {
        _next = next;
        Speed = speed;
        _paused = paused;
        _feed = feed;
        _loop = Create();
    }

    /// <summary>Cycles of the current match's regular time.</summary>
    public int Cycles
    {
        get
        {
            lock (_gate)
            {
                return _loop.Cycles;
            }
        }
    }

    /// <summary>Multiple of real time.</summary>
    public double Speed { get; }

    /// <summary>The match being played (a new one after a restart).</summary>
    public Match Match
    {
        get
        {
            lock (_gate)
            {
                return _loop.Match;
            }
        }
    }

    /// <summary>Time spent computing the current match's cycles (for the summary).</summary>
    public TimeSpan Busy => _busy.Elapsed;

    /// <summary>
    /// Wall time of the current match: from the start of its first cycle to the end of its last
    /// (or to now, while it is played), pauses included.
    /// </summary>
    public TimeSpan Played => _played.Elapsed;

    /// <summary>
    /// Told on the playing thread, with the match, as soon as a match is over (after its last
    /// cycle is published, before the status that says it is over); again for each restarted match
    /// that ends.
    /// </summary>
    public Action<Match>? Ended { get; set; }

    /// <summary>Stops after the current cycle until <see cref="Resume"/> or <see cref="Step"/>.</summary>
    public void Pause() => Change(() => _paused = true);

    /// <summary>Plays on in real time.</summary>
    public void Resume() => Change(() =>
    {
        _paused = false;
        _steps = 0;
    });

    /// <summary>Plays exactly one more cycle, then stays paused.</summary>
    public void Step() => Change(() =>
    {
        _paused = true;
        _steps++;
    });

    /// <summary>Starts the match again from cycle 0 (the settings <c>next</c> gives then), paused or playing as before.</summary>
    public void Restart() => Change(() => _restart = true);

    /// <summary>Starts the match again from cycle 0 (the settings <c>next</c> gives then) and plays it.</summary>
    public void Start() => Change(() =>
    {
        _restart = true;
        _paused = false;
        _steps = 0;
    });

    /// <summary>Applies a viewer's control action: <c>pause</c>, <c>resume</c>, <c>step</c> or <c>restart</c>; false for anything else.</summary>
    public bool Control(string action)
    {
        switch (action)
        {
            case "pause": Pause(); return true;
            case "resume": Resume(); return true;
            case "step": Step(); return true;
            case "restart": Restart(); return true;
            default: return false;
        }
    }

    /// <summary>Plays until <paramref name="stop"/> is cancelled (runs on the caller's thread).</summary>
    public void Run(CancellationToken stop)
    {
        using var wake = stop.Register(() => Change(static () => { }));
        Begin();
        TimeSpan interval = TimeSpan.FromMilliseconds(100 / Speed);
        var clock = Stopwatch.StartNew();
        TimeSpan deadline = TimeSpan.Zero;
        while (!stop.IsCancellationRequested)
        {
            bool stepping, restart = false, changed;
            lock (_gate)
            {
                changed = _statusChanged;
                _statusChanged = false;
            }

            if (changed)
            {
                PublishStatus(); // from this thread only, so a status never overtakes a cycle it counts
            }

            lock (_gate)
            {
                if (_restart)
                {
                    _restart = false;
                    restart = true;
                    stepping = false;
                }
                else if (Over || (_paused && _steps == 0))
                {
                    Monitor.Wait(_gate);
                    deadline = clock.Elapsed;
                    continue;
                }
                else if (!_paused && deadline - clock.Elapsed is { Ticks: > 0 } left)
                {
                    Monitor.Wait(_gate, left); // the clock read once: read twice, the wait could come out negative on a busy machine
                    continue;
                }
                else
                {
                    stepping = _paused;
                    _steps -= stepping ? 1 : 0;
                }
            }

            if (restart)
            {
                MatchLoop old;
                lock (_gate)
                {
                    old = _loop;
                }

                old.Dispose(); // its strategies stop before the next match's start (a remote team's client goes on to it)
                var fresh = Create();
                lock (_gate)
                {
                    _loop = fresh;
                }

                _busy.Reset();
                _played.Reset();
                Begin();
                deadline = clock.Elapsed;
                continue;
            }

            _played.Start(); // the first cycle starts the match's wall time; it runs on through pauses
            _busy.Start();
            _loop.Step(); // publishes the cycle's line
            _busy.Stop();
            if (Over)
            {
                _played.Stop();
                Ended?.Invoke(_loop.Match); // before the status that says so: a viewer told "over" finds the summary written
            }

            if (stepping || Over)
            {
                PublishStatus();
            }

            // The next cycle is due one interval after this one was (or now, if far behind).
            deadline = clock.Elapsed - deadline > interval ? clock.Elapsed + interval : deadline + interval;
        }
    }

    private bool Over => _loop.IsOver;

    private MatchLoop Create()
    {
        var (match, cycles) = _next();
        return new MatchLoop(match, cycles, this);
    }

    private void Begin()
    {
        _feed.Reset();
        _loop.Start(); // publishes the cycle-0 line
        PublishStatus();
    }

    private void Change(Action change)
    {
        lock (_gate)
        {
            change();
            _statusChanged = true;
            Monitor.PulseAll(_gate);
        }
    }

    /// <summary>Publishes a cycle line of the match to the viewers (called by the loop on the playing thread).</summary>
    void ITraceSink.WriteLine(ReadOnlySpan<byte> line)
    {
        var message = new byte[DataPrefix.Length + line.Length + MessageEnd.Length];
        DataPrefix.CopyTo(message, 0);
        line.CopyTo(message.AsSpan(DataPrefix.Length));
        MessageEnd.CopyTo(message, DataPrefix.Length + line.Length);
        _feed.Publish(message);
    }

    private void PublishStatus()
    {
        string status;
        lock (_gate)
        {
            status = string.Create(CultureInfo.InvariantCulture,
                $"event: status\ndata: {{\"paused\":{(_paused ? "true" : "false")},\"speed\":{Speed:R},\"cycle\":{_loop.Match.World.Cycle},\"cycles\":{_loop.Cycles},\"over\":{(Over ? "true" : "false")}}}\n\n");
        }

        _feed.Publish(Encoding.UTF8.GetBytes(status));
    }
}
