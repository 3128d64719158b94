using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;

namespace URWPGSim2D.Engine.Messages;

/// <summary>Text helpers for one-line messages.</summary>
public static class MessageText
{
    /// <summary>A user-supplied string as a JSON string literal (quoted, control characters escaped), so a message stays on one line.</summary>
    /// <param name="value">Any string.</param>
    /// <returns>E.g. <c>"triangle"</c>, or <c>"tri\nangle"</c> for a string holding a line break.</returns>
    public static string Quote(string value) =>
        $"\"{JsonEncodedText.Encode(value, JavaScriptEncoder.UnsafeRelaxedJsonEscaping)}\"";

    /// <summary>
    /// Any text made safe for a one-line message: line breaks, other control characters, the
    /// Unicode line and paragraph separators and lone surrogates become escapes (<c>\n</c>,
    /// <c>\u2028</c>, …); a backslash stays as it is. Every error line the program writes passes through this.
    /// </summary>
    /// <param name="value">Any text.</param>
    /// <returns>The same text when it is already safe (no copy), else the escaped text.</returns>
    public static string Escape(string value)
    {
        int first = 0;
        while (first < value.Length && IsSafe(value, first))
        {
            first++;
        }

        if (first == value.Length)
        {
            return value;
        }

        var text = new StringBuilder(value.Length + 16).Append(value, 0, first);
        for (int i = first; i < value.Length; i++)
        {
            char c = value[i];
            if (IsSafe(value, i))
            {
                text.Append(c);
                if (char.IsHighSurrogate(c))
                {
                    text.Append(value[++i]);
                }
            }
            else
            {
                text.Append(c switch
                {
                    '\n' => "\\n",
                    '\r' => "\\r",
                    '\t' => "\\t",
                    _ => $"\\u{(int)c:x4}",
                });
            }
        }

        return text.ToString();
    }

    // True when value[i] may stand in a one-line message as it is (a high surrogate only with its low half).
    private static bool IsSafe(string value, int i)
    {
        char c = value[i];
        if (char.IsHighSurrogate(c))
        {
            return i + 1 < value.Length && char.IsLowSurrogate(value[i + 1]);
        }

        if (char.IsLowSurrogate(c))
        {
            return i > 0 && char.IsHighSurrogate(value[i - 1]);
        }

        return !char.IsControl(c) && c is not '\u2028' and not '\u2029';
    }
}
