namespace URWPGSim2D.Engine.Items;

/// <summary>
/// Something the referee of an item saw happen: a goal, a catch, a ball in its hole, half time, the
/// end. Reported in the summary and on the trace line of <see cref="Cycle"/>. Absent members are −1
/// (<see cref="Team"/>, <see cref="Fish"/>, <see cref="Ball"/>) or NaN (<see cref="Value"/>).
/// </summary>
/// <param name="Cycle">The cycle it happened in (1-based).</param>
/// <param name="Kind">goal, catch, ball-in-hole, half-time, end, … (the trace contract's kinds).</param>
/// <param name="Team">The team it counts for, or −1.</param>
/// <param name="Fish">The fish (index into the match's fish), or −1.</param>
/// <param name="Ball">The ball index, or −1.</param>
/// <param name="Value">Points it scored, or NaN.</param>
/// <param name="Text">A short human-readable line.</param>
public readonly record struct ItemEvent(int Cycle, string Kind, int Team, int Fish, int Ball, double Value, string Text)
{
    /// <summary>An event without team, fish, ball or value.</summary>
    public static ItemEvent Plain(int cycle, string kind, string text) => new(cycle, kind, -1, -1, -1, double.NaN, text);
}
