using System.Text;

namespace URWPGSim2D.Engine.Teams;

/// <summary>
/// What one team's strategy printed during one cycle's call (<c>Console.Out</c>, <c>Console.Error</c>,
/// <c>System.Diagnostics.Debug</c>), kept up to <see cref="MaxChars"/> characters per cycle; what is
/// over is counted, not kept, so a chatty strategy cannot fill memory or the trace.
/// </summary>
public sealed class StrategyLog
{
    /// <summary>Characters kept per team and cycle.</summary>
    public const int MaxChars = 4096;

    private readonly StringBuilder _text = new(256);

    /// <summary>Characters printed past <see cref="MaxChars"/> since <see cref="Clear"/>.</summary>
    public int Dropped { get; private set; }

    /// <summary>Characters kept since <see cref="Clear"/>.</summary>
    public int Length => _text.Length;

    /// <summary>Forgets the last cycle's output.</summary>
    public void Clear()
    {
        _text.Clear();
        Dropped = 0;
    }

    /// <summary>Adds printed text, within the bound.</summary>
    public void Append(ReadOnlySpan<char> text)
    {
        int room = MaxChars - _text.Length;
        if (text.Length > room)
        {
            Dropped += text.Length - Math.Max(room, 0);
            text = text[..Math.Max(room, 0)];
        }

        _text.Append(text);
    }

    /// <summary>Adds text a client sent and the characters it dropped, within the bound.</summary>
    public void Add(StringBuilder text, int dropped)
    {
        foreach (var chunk in text.GetChunks())
        {
            Append(chunk.Span);
        }

        Dropped += dropped;
    }

    /// <summary>The text kept, without the note of what was dropped.</summary>
    public string Kept => _text.ToString();

    /// <summary>Adds another log's text (a call that ran on another thread or process), within the bound.</summary>
    public void AppendFrom(StrategyLog other)
    {
        foreach (var chunk in other._text.GetChunks())
        {
            Append(chunk.Span);
        }

        Dropped += other.Dropped;
    }

    /// <summary>The text kept, with a note of what was dropped.</summary>
    public override string ToString() =>
        Dropped == 0 ? _text.ToString() : _text.ToString() + $"\n… {Dropped} more characters dropped (at most {MaxChars} a cycle)";
}
