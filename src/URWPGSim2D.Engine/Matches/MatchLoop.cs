using System.Linq;
using System.Threading;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Matches;

/// <summary>
/// The one loop that plays a match, used by every command that plays one (<c>run</c>, batches, the
/// live view, tournaments). It writes the cycle-0 trace line, then plays cycle after cycle until the
/// match is over, writing each cycle's line to the trace sinks, and stops the strategies when done.
/// A match is over when its item's referee ends it (a tied polo match plays its extra time and
/// penalties, up to <see cref="MaxCycles"/>) or, for a scene without an end of its own, after
/// <see cref="Cycles"/> cycles.
/// </summary>
/// <remarks>
/// <para>Whole match: <c>using var loop = new MatchLoop(settings.Build(), settings.Cycles, sinks); loop.Play(cancel);</c>
/// then read <see cref="Match"/> (scores, statistics, faults). Cycle by cycle (the live view paces,
/// pauses and steps): <see cref="Start"/> once, then <see cref="Step"/> while <see cref="IsOver"/> is false.</para>
/// <para>Not thread-safe: one thread plays a loop. Disposing it stops the match's strategy hosts.</para>
/// </remarks>
public sealed class MatchLoop : IDisposable
{
    private readonly ITraceSink[] _sinks;
    private readonly TraceLine? _lines;
    private bool _started;

    /// <summary>Creates the loop of a freshly built match (cycle 0).</summary>
    /// <param name="match">The match (freshly built, at cycle 0).</param>
    /// <param name="cycles">Cycles of regular time (the cycles the match was built for).</param>
    /// <param name="trace">Where each cycle's trace line goes; nulls are skipped (none: no line is made).</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="cycles"/> is below 0.</exception>
    public MatchLoop(Match match, int cycles, params ITraceSink?[] trace)
    {
        ArgumentNullException.ThrowIfNull(match);
        ArgumentOutOfRangeException.ThrowIfNegative(cycles);
        Match = match;
        Cycles = cycles;
        _sinks = [.. (trace ?? []).OfType<ITraceSink>()];
        _lines = _sinks.Length == 0 ? null : new TraceLine(match.World, match.Teams, match.Rules);
    }

    /// <summary>The match played.</summary>
    public Match Match { get; }

    /// <summary>Cycles of regular time.</summary>
    public int Cycles { get; }

    /// <summary>The most cycles the match can last: the item's referee's (extra periods deciding a tie), else <see cref="Cycles"/>.</summary>
    public int MaxCycles => Match.Referee?.MaxCycles ?? Cycles;

    /// <summary>Whether the match is over: its item ended it, or it reached <see cref="MaxCycles"/>.</summary>
    public bool IsOver => Match.IsOver || Match.World.Cycle >= MaxCycles;

    /// <summary>Writes the cycle-0 line (once; <see cref="Step"/> does it if not done).</summary>
    public void Start()
    {
        if (!_started)
        {
            _started = true;
            Write(ReadOnlySpan<ContactRecord>.Empty);
        }
    }

    /// <summary>Plays one cycle and writes its line, unless the match is over; returns whether a cycle was played.</summary>
    public bool Step()
    {
        Start();
        if (IsOver)
        {
            return false;
        }

        Match.Step();
        Write(Match.Contacts.Cycle);
        return true;
    }

    /// <summary>Plays the match to its end (or until <paramref name="cancel"/> is cancelled, checked between cycles), then stops its strategies.</summary>
    /// <param name="cancel">Ends the match early: the cycles played so far stay played and written.</param>
    /// <param name="played">Told the world's cycle after each cycle played (e.g. a progress bar).</param>
    public void Play(CancellationToken cancel = default, Action<int>? played = null)
    {
        try
        {
            Start();
            while (!cancel.IsCancellationRequested && Step())
            {
                played?.Invoke(Match.World.Cycle);
            }
        }
        finally
        {
            Dispose();
        }
    }

    /// <summary>Stops the match's strategy hosts (idempotent), telling them the cycles played and the final score.</summary>
    public void Dispose() => StopStrategies(Match);

    /// <summary>Stops <paramref name="match"/>'s strategies, telling hosts the cycles played and the final score.</summary>
    public static void StopStrategies(Match match)
    {
        match.Teams.Stop(match.World.Cycle, match.Rules.Scores);
    }

    private void Write(ReadOnlySpan<ContactRecord> contacts)
    {
        if (_lines is null)
        {
            return;
        }

        var line = _lines.Write(contacts);
        foreach (var sink in _sinks)
        {
            sink.WriteLine(line);
        }
    }
}
