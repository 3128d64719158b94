using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Server.Tests.Trace;

/// <summary>A trace sink that keeps the bytes a trace file would hold (each line and its newline).</summary>
internal sealed class TraceBytes : ITraceSink
{
    private readonly MemoryStream _bytes = new();

    /// <inheritdoc/>
    public void WriteLine(ReadOnlySpan<byte> line)
    {
        _bytes.Write(line);
        _bytes.WriteByte((byte)'\n');
    }

    /// <summary>The trace so far.</summary>
    public byte[] ToArray() => _bytes.ToArray();

    /// <summary>The trace of <paramref name="match"/> played by the match loop for <paramref name="cycles"/> cycles.</summary>
    public static byte[] Of(Match match, int cycles, Action<int>? played = null)
    {
        var sink = new TraceBytes();
        using var loop = new MatchLoop(match, cycles, sink);
        loop.Play(played: played);
        return sink.ToArray();
    }
}
