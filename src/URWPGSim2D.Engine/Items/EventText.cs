using System.Globalization;
using System.Runtime.CompilerServices;

namespace URWPGSim2D.Engine.Items;

/// <summary>
/// The text of a referee's event, built from an interpolated string in the invariant culture when
/// the referee keeps event texts (<see cref="ItemReferee.EventTexts"/>); otherwise its holes are not
/// even evaluated and the text is empty, so recording the event allocates nothing.
/// </summary>
[InterpolatedStringHandler]
internal ref struct EventText
{
    private DefaultInterpolatedStringHandler _text;
    private readonly bool _on;

    /// <summary>Starts the text of an event <paramref name="referee"/> records.</summary>
    public EventText(int literalLength, int formattedCount, ItemReferee referee, out bool shouldAppend)
    {
        _on = shouldAppend = referee.EventTexts;
        _text = _on ? new DefaultInterpolatedStringHandler(literalLength, formattedCount, CultureInfo.InvariantCulture) : default;
    }

    /// <summary>Appends literal text.</summary>
    public void AppendLiteral(string value) => _text.AppendLiteral(value);

    /// <summary>Appends a value.</summary>
    public void AppendFormatted<T>(T value) => _text.AppendFormatted(value);

    /// <summary>Appends a value in <paramref name="format"/>.</summary>
    public void AppendFormatted<T>(T value, string? format) => _text.AppendFormatted(value, format);

    /// <summary>Appends a string.</summary>
    public void AppendFormatted(string? value) => _text.AppendFormatted(value);

    /// <summary>The text (empty when texts are off), releasing the buffer.</summary>
    public string ToStringAndClear() => _on ? _text.ToStringAndClear() : string.Empty;
}
