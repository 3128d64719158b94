using System.Globalization;
using System.Text;
using System.Text.Json;

namespace URWPGSim2D.Engine.Messages;

/// <summary>
/// Finds a JSON string or property name whose escapes leave a lone UTF-16 surrogate
/// (<c>"\ud800"</c>): well-formed JSON that System.Text.Json refuses only when the text is read
/// (an <see cref="InvalidOperationException"/>). The readers turn that into a bad-input line.
/// </summary>
public static class LoneSurrogate
{
    /// <summary>The message for the first such string of <paramref name="text"/>: where it is and why it is refused.</summary>
    /// <param name="text">The whole JSON input.</param>
    /// <param name="options">The reader options the input was parsed with (comments, trailing commas).</param>
    /// <returns>E.g. <c>invalid text at line 3, column 17: a lone UTF-16 surrogate escape (\ud800 to \udfff without its pair)</c>.</returns>
    public static string Describe(string text, JsonReaderOptions options)
    {
        byte[] utf8 = Encoding.UTF8.GetBytes(text);
        long at = Find(utf8, options);
        string where = at < 0 ? "somewhere" : Where(utf8, at);
        return $"invalid text at {where}: a lone UTF-16 surrogate escape (\\ud800 to \\udfff without its pair)";
    }

    // The byte offset of the first string token that cannot be decoded, or -1.
    private static long Find(byte[] utf8, JsonReaderOptions options)
    {
        var reader = new Utf8JsonReader(utf8, options);
        try
        {
            while (reader.Read())
            {
                if (reader.TokenType is JsonTokenType.String or JsonTokenType.PropertyName && reader.ValueIsEscaped)
                {
                    try
                    {
                        _ = reader.GetString();
                    }
                    catch (InvalidOperationException)
                    {
                        return reader.TokenStartIndex;
                    }
                }
            }
        }
        catch (JsonException)
        {
            // A syntax error further on: the reader of the caller reports it.
        }

        return -1;
    }

    private static string Where(byte[] utf8, long offset)
    {
        long line = 1, lineStart = 0;
        for (long i = 0; i < offset; i++)
        {
            if (utf8[i] == (byte)'\n')
            {
                line++;
                lineStart = i + 1;
            }
        }

        return string.Create(CultureInfo.InvariantCulture, $"line {line}, column {offset - lineStart + 1}");
    }
}
