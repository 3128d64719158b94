namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// Where a match's trace lines go as it is played (<see cref="Matches.MatchLoop"/>): a trace
/// file, a replay page, the live view, a test's hash. Each line is one cycle's JSON object
/// (<see cref="TraceLine"/>), without its newline; the span is valid only during the call.
/// </summary>
public interface ITraceSink
{
    /// <summary>Receives the next cycle line (cycle 0 first, then one per cycle played, in order).</summary>
    void WriteLine(ReadOnlySpan<byte> line);
}
