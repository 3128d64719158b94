using System.IO;

namespace URWPGSim2D.Protocol;

/// <summary>
/// JSON Lines framing over a stream (a host's pipes or a TCP connection): reads one line at a time
/// into a reused buffer and writes whole lines, each followed by <c>\n</c> and flushed. Nothing is
/// allocated per line once the buffer has grown to the longest line.
/// </summary>
public sealed class LineChannel
{
    private readonly Stream _input;
    private readonly Stream _output;
    private readonly int _maxLine;
    private byte[] _buffer = new byte[16 * 1024];
    private int _start;
    private int _end;

    /// <summary>Creates the channel; lines longer than <paramref name="maxLineBytes"/> are refused.</summary>
    public LineChannel(Stream input, Stream output, int maxLineBytes)
    {
        _input = input;
        _output = output;
        _maxLine = maxLineBytes;
    }

    /// <summary>
    /// Reads the next line (without its <c>\n</c>, and without a <c>\r</c> before it). The span is valid
    /// until the next call. Returns false at the end of the stream (a partial last line is dropped).
    /// </summary>
    /// <exception cref="ProtocolException">The line is longer than the limit.</exception>
    public bool TryReadLine(out ReadOnlySpan<byte> line)
    {
        int scanned = 0;
        while (true)
        {
            int nl = _buffer.AsSpan(_start + scanned, _end - _start - scanned).IndexOf((byte)'\n');
            if (nl >= 0)
            {
                int length = scanned + nl;
                if (length > _maxLine + 1 || (length == _maxLine + 1 && _buffer[_start + length - 1] != '\r'))
                {
                    _start += length + 1; // the next read starts after it
                    throw new ProtocolException($"a line is longer than {_maxLine} bytes");
                }

                line = _buffer.AsSpan(_start, length > 0 && _buffer[_start + length - 1] == '\r' ? length - 1 : length);
                _start += length + 1;
                return true;
            }

            scanned = _end - _start;
            if (scanned > _maxLine)
            {
                throw new ProtocolException($"a line is longer than {_maxLine} bytes");
            }

            if (_start > 0)
            {
                Buffer.BlockCopy(_buffer, _start, _buffer, 0, scanned);
                _end = scanned;
                _start = 0;
            }

            if (_end == _buffer.Length)
            {
                Array.Resize(ref _buffer, Math.Min(_buffer.Length * 2, _maxLine + 2));
            }

            int read = _input.Read(_buffer, _end, _buffer.Length - _end);
            if (read <= 0)
            {
                line = default;
                return false;
            }

            _end += read;
        }
    }

    /// <summary>Writes one whole line, which ends with its <c>\n</c> (as <see cref="MessageWriter"/> makes them), in one write, then flushes.</summary>
    public void WriteLine(ReadOnlySpan<byte> line)
    {
        if (line.IsEmpty || line[^1] != (byte)'\n')
        {
            throw new ArgumentException("a line must end with \\n", nameof(line));
        }

        _output.Write(line);
        _output.Flush();
    }
}
