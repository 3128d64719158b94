namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// One event of a cycle in the trace's <c>"events"</c> array: a kind (<c>goal</c>, <c>catch</c>,
/// <c>ball-in-hole</c>, <c>rescue</c>, <c>foul</c>, <c>sent-off</c>, <c>half-time</c>, <c>end</c>,
/// <c>touch</c>, <c>target</c>, <c>fault</c> (a team's strategy fault) or an item's own), a short human-readable text (always written, so
/// a viewer can show any kind) and the optional team, fish, ball and value it concerns.
/// </summary>
/// <param name="Kind">Event kind, lower-case with dashes.</param>
/// <param name="Text">Short text, e.g. <c>team 0 scores ball 2</c>.</param>
/// <param name="Team">Team index, or null.</param>
/// <param name="Fish">Index into the line's <c>fish</c> array, or null.</param>
/// <param name="Ball">Ball index, or null.</param>
/// <param name="Value">A number (points, time, …), or null.</param>
internal readonly record struct TraceEvent(string Kind, string Text, int? Team = null, int? Fish = null, int? Ball = null, double? Value = null);
