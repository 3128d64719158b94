using System;
using System.Diagnostics;
using System.Globalization;
using System.Text;
using System.Threading;
using URWPGSim2D.Server.Simulation;
using URWPGSim2D.Server.Trace;

namespace URWPGSim2D.Server.Viewer;

/// <summary>
/// Plays a match for the live view on its own thread, one cycle every 100 ms / speed (deadline
/// based, so it does not drift), publishing each cycle's trace line and the play status to a
/// <see cref="LiveFeed"/>. Pause, resume, step and restart come from any thread (the viewers'
/// buttons); a step plays exactly one cycle and leaves the match paused. Only the playing thread
/// publishes, so a status message always follows every cycle line it counts. At the last cycle the
/// match is over and waits (a restart plays it again) until <see cref="Run"/> is cancelled.
/// </summary>
internal sealed class LiveMatch
{
    private static readonly byte[] DataPrefix = "data: "u8.ToArray();
    private static readonly byte[] MessageEnd = "\n\n"u8.ToArray();

    private readonly Func<Match> _create;
    private readonly LiveFeed _feed;
    private readonly object _gate = new();
    private readonly Stopwatch _busy = new();
    private Match _match;
    private TraceLine _lines;
    private bool _paused;
    private int _steps;
    private bool _restart;
    private bool _statusChanged;

    /// <summary>Creates the player; the first match is built at once.</summary>
    /// <param name="create">Builds a fresh match (called again on restart).</param>
    /// <param name="cycles">Cycles of a match.</param>
    /// <param name="speed">Multiple of real time (1: 100 ms a cycle).</param>
    /// <param name="paused">Whether to wait for resume or step before the first cycle.</param>
    /// <param name="feed">Where cycles and status go.</param>
    public LiveMatch(Func<Match> create, int cycles, double speed, bool paused, LiveFeed feed)
    {
        _create = create;
        Cycles = cycles;
        Speed = speed;
        _paused = paused;
        _feed = feed;
        _match = create();
        _lines = new TraceLine(_match);
    }

    /// <summary>Cycles of a match.</summary>
    public int Cycles { get; }

    /// <summary>Multiple of real time.</summary>
    public double Speed { get; }

    /// <summary>The match being played (a new one after a restart).</summary>
    public Match Match
    {
        get
        {
            lock (_gate)
            {
                return _match;
            }
        }
    }

    /// <summary>Time spent playing cycles (for the summary).</summary>
    public TimeSpan Busy => _busy.Elapsed;

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

    /// <summary>Starts the match again from cycle 0 (same scenario, seed and strategies).</summary>
    public void Restart() => Change(() => _restart = true);

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
                else if (!_paused && clock.Elapsed < deadline)
                {
                    Monitor.Wait(_gate, deadline - clock.Elapsed);
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
                var fresh = _create();
                Match old;
                lock (_gate)
                {
                    old = _match;
                    _match = fresh;
                    _lines = new TraceLine(fresh);
                }

                old.Strategies.Stop();

                Begin();
                deadline = clock.Elapsed;
                continue;
            }

            _busy.Start();
            _match.Step();
            _busy.Stop();
            Publish(_lines.Write(_match.Contacts.Cycle));
            if (stepping || Over)
            {
                PublishStatus();
            }

            // The next cycle is due one interval after this one was (or now, if far behind).
            deadline = clock.Elapsed - deadline > interval ? clock.Elapsed + interval : deadline + interval;
        }
    }

    private bool Over => _match.World.Cycle >= Cycles || _match.IsOver; // an item may end early

    private void Begin()
    {
        _feed.Reset();
        Publish(_lines.Write(ReadOnlySpan<ContactRecord>.Empty));
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

    private void Publish(ReadOnlySpan<byte> line)
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
                $"event: status\ndata: {{\"paused\":{(_paused ? "true" : "false")},\"speed\":{Speed:R},\"cycle\":{_match.World.Cycle},\"cycles\":{Cycles},\"over\":{(Over ? "true" : "false")}}}\n\n");
        }

        _feed.Publish(Encoding.UTF8.GetBytes(status));
    }
}
