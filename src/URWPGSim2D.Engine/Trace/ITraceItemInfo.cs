namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// What a competition item adds to the trace (CONTRACT: docs/viewer.md, "Trace additions"): its
/// slug, its zones and ball values on the cycle-0 line, and on every line the score and the
/// cycle's events. Every match's rules implement it (an item's referee; a plain match's goal
/// rule, slug <c>default</c>, goals only) and <see cref="TraceLine"/> reads them. Each cycle, after it was played, the
/// trace calls <see cref="AddEvents"/> (not for cycle 0) and then <see cref="Score"/> per team;
/// <see cref="Slug"/>, <see cref="Zones"/> and <see cref="BallValue"/> only for the cycle-0 line.
/// </summary>
internal interface ITraceItemInfo
{
    /// <summary>The item's slug (<c>"default"</c> for a plain match), written as <c>"item"</c> on the cycle-0 line.</summary>
    string Slug { get; }

    /// <summary>The item's static zones (holes, targets, forbidden areas, …), written in <c>layout.zones</c>; may be empty.</summary>
    IReadOnlyList<TraceZone> Zones { get; }

    /// <summary>The value of ball <paramref name="ball"/> (e.g. its points), or null when the item gives balls no value.</summary>
    /// <param name="ball">Ball index (ballN).</param>
    double? BallValue(int ball);

    /// <summary>The score of team <paramref name="team"/> (0 or 1) after the cycle just played (asked after <see cref="AddEvents"/>).</summary>
    /// <param name="team">Team index.</param>
    double Score(int team);

    /// <summary>Adds the events of cycle <paramref name="cycle"/> (the one just played) to <paramref name="events"/>.</summary>
    /// <param name="cycle">The cycle number (≥ 1; never called for cycle 0).</param>
    /// <param name="events">The list to append to (cleared by the caller).</param>
    void AddEvents(int cycle, List<TraceEvent> events);
}
