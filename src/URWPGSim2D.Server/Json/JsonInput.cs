using System.Text.Json;
using System.Text.Json.Serialization.Metadata;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// Reads a whole input document with source-generated metadata and turns every
/// <see cref="JsonException"/> into a one-line <see cref="InputException"/> naming the
/// path, line and column of the problem.
/// </summary>
internal static class JsonInput
{
    /// <summary>Describes the JSON expected at a path, e.g. "a number"; null when unknown.</summary>
    /// <param name="path">The steps after the root.</param>
    /// <returns>A phrase for "expected ..." messages, or null.</returns>
    public delegate string? ExpectedKind(ReadOnlySpan<JsonPathSegment> path);

    /// <summary>Deserializes <paramref name="text"/>.</summary>
    /// <typeparam name="T">The document type.</typeparam>
    /// <param name="text">The whole input.</param>
    /// <param name="typeInfo">Source-generated metadata of <typeparamref name="T"/>.</param>
    /// <param name="rootName">The user-facing name of the whole document, e.g. <c>pairs</c>.</param>
    /// <param name="expectedKind">The schema, for type-mismatch messages.</param>
    /// <returns>The document; null when the input is the JSON literal <c>null</c>.</returns>
    /// <exception cref="InputException">Empty input, malformed JSON, or a value of the wrong JSON type.</exception>
    public static T? Deserialize<T>(string text, JsonTypeInfo<T> typeInfo, string rootName, ExpectedKind expectedKind)
    {
        if (string.IsNullOrWhiteSpace(text))
        {
            throw new InputException(rootName, "input is empty");
        }

        try
        {
            return JsonSerializer.Deserialize(text, typeInfo);
        }
        catch (JsonException ex)
        {
            throw ToInputError(ex, rootName, expectedKind);
        }
        catch (InvalidOperationException)
        {
            throw new InputException(rootName, LoneSurrogate.Describe(text, default));
        }
    }

    private static InputException ToInputError(JsonException ex, string rootName, ExpectedKind expectedKind)
    {
        string path = InputPath.FromSerializerPath(ex.Path, rootName);
        long line = (ex.LineNumber ?? 0) + 1;
        long position = ex.BytePositionInLine ?? 0;

        // The reader's own exception (a JsonException too) marks a syntax error, at the 0-based
        // position of the offending byte. Any other cause is a well-formed value of the wrong
        // kind, reported just after its token: the 1-based column of the token's last byte.
        if (ex.InnerException is JsonException syntax)
        {
            return new InputException(path, $"malformed JSON at {Where(line, position + 1)}: {ReaderMessage(syntax.Message)}");
        }

        var segments = InputPath.Parse(ex.Path);
        string? expected = segments is null ? null : expectedKind(segments);
        string where = Where(line, Math.Max(position, 1));
        return new InputException(path, expected is null ? $"wrong JSON type at {where}" : $"expected {expected} at {where}");
    }

    // Lines and columns count from 1; columns count UTF-8 bytes.
    private static string Where(long line, long column) =>
        string.Create(CultureInfo.InvariantCulture, $"line {line}, column {column}");

    // The reader appends " LineNumber: n | BytePositionInLine: m." to its message; the position is reported separately.
    private static string ReaderMessage(string message)
    {
        int cut = message.IndexOf(" LineNumber:", StringComparison.Ordinal);
        return (cut < 0 ? message : message[..cut]).ReplaceLineEndings(" ");
    }
}
