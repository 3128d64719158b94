using System.Text.Json;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// Which of its two forms a <c>render</c> input has: an array of SHAPEs, or an array of
/// <c>{"a": SHAPE, "b": SHAPE}</c> pairs. Decided by the first element alone: it is a pair when
/// it is an object with an <c>"a"</c> or <c>"b"</c> field and no <c>"type"</c> field (a segment
/// SHAPE also has <c>a</c> and <c>b</c>, but always a <c>type</c>); anything else — including an
/// empty array and input that is not valid JSON — is read as SHAPEs, whose parser then reports
/// the problem.
/// </summary>
internal static class RenderInputKind
{
    /// <summary>Whether the document is an array of pairs.</summary>
    /// <param name="text">The whole input.</param>
    /// <returns>True for pairs, false for SHAPEs.</returns>
    public static bool IsPairs(string text)
    {
        var reader = new Utf8JsonReader(Encoding.UTF8.GetBytes(text.TrimStart('\uFEFF')), new JsonReaderOptions { CommentHandling = JsonCommentHandling.Disallow });
        bool hasAOrB = false;
        try
        {
            if (!reader.Read() || reader.TokenType != JsonTokenType.StartArray || !reader.Read() || reader.TokenType != JsonTokenType.StartObject)
            {
                return false;
            }

            while (reader.Read() && reader.TokenType == JsonTokenType.PropertyName)
            {
                if (reader.ValueTextEquals("type"u8))
                {
                    return false;
                }

                hasAOrB |= reader.ValueTextEquals("a"u8) || reader.ValueTextEquals("b"u8);
                if (!reader.Read() || !reader.TrySkip())
                {
                    break;
                }
            }
        }
        catch (Exception e) when (e is JsonException or InvalidOperationException)
        {
            // Malformed (or a name that is not valid UTF-16) after what was seen: decide from that;
            // the parser reports the error.
        }

        return hasAOrB;
    }
}
