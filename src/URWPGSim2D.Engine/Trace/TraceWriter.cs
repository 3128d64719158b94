using System.IO;

namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// Writes the match as JSON Lines: the initial state as cycle 0 (with the item and the static
/// layout), then one line per cycle (<see cref="TraceLine"/>: fish, balls, contacts, score,
/// events). Numbers use the shortest round-trip form, so the same match gives the same bytes. The file is
/// written under a temporary name beside the target and renamed by <see cref="Complete"/>; if the
/// run fails, <see cref="Dispose"/> deletes it, so no half trace is left.
/// </summary>
public sealed class TraceWriter : ITraceSink, IDisposable
{
    private static readonly byte[] NewLine = [(byte)'\n'];

    private readonly string _path;
    private readonly string _temporary;
    private readonly FileStream _stream;
    private bool _completed;

    /// <summary>Starts writing the trace to <paramref name="path"/> (through a <c>.partial</c> file beside it, renamed when complete).</summary>
    /// <param name="path">The trace file.</param>
    public TraceWriter(string path)
    {
        _path = Path.GetFullPath(path);
        _temporary = _path + ".partial";
        _stream = new FileStream(_temporary, FileMode.Create, FileAccess.Write, FileShare.None, 1 << 16);
    }

    /// <summary>Writes one line made by <see cref="TraceLine.Write"/> and its newline.</summary>
    public void WriteLine(ReadOnlySpan<byte> line)
    {
        _stream.Write(line);
        _stream.Write(NewLine);
    }

    /// <summary>Flushes the trace and moves it to its final name.</summary>
    public void Complete()
    {
        _stream.Dispose();
        File.Move(_temporary, _path, overwrite: true);
        _completed = true;
    }

    /// <summary>Closes the file; an incomplete trace is deleted.</summary>
    public void Dispose()
    {
        if (_completed)
        {
            return;
        }

        _stream.Dispose();
        File.Delete(_temporary);
    }
}
