using System.Text.Json;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The largest inputs each command accepts (docs/cli.md, "Limits"). Beyond them a command stops
/// before any work with one line and exit code 2, instead of running for minutes and gigabytes:
/// every limit is checked on the raw input, with memory proportional to it.
/// </summary>
internal static class InputLimits
{
    /// <summary>Largest input file or standard input of any command, in bytes (64 MiB).</summary>
    public const long InputBytes = 64L << 20;

    /// <summary>Most pairs <c>collide</c> reads.</summary>
    public const int Pairs = 200_000;

    /// <summary>Most SHAPEs <c>shapes</c> reads.</summary>
    public const int Shapes = 100_000;

    /// <summary>Most SHAPEs or pairs <c>render</c> draws (a bigger picture is no use to look at).</summary>
    public const int RenderElements = 10_000;

    /// <summary>The message for an input above <see cref="InputBytes"/>.</summary>
    public static string TooLarge(long bytes) =>
        string.Create(CultureInfo.InvariantCulture, $"the input is {bytes} bytes, more than the limit of {InputBytes >> 20} MiB (docs/cli.md, Limits)");

    /// <summary>
    /// Fails when the top-level JSON array of <paramref name="text"/> has more than
    /// <paramref name="limit"/> elements. Counted with a forward-only reader (no document is
    /// built); text that is not such an array, or malformed, passes: the parser reports it.
    /// </summary>
    /// <param name="text">The whole input.</param>
    /// <param name="rootName">The document's name in messages, e.g. <c>pairs</c>.</param>
    /// <param name="limit">The most elements allowed.</param>
    /// <param name="command">The command, for the message.</param>
    /// <exception cref="InputException">More elements than the limit.</exception>
    public static void CheckCount(string text, string rootName, int limit, string command)
    {
        if (text.Length <= 2L * limit)
        {
            return; // an element and its comma take at least two characters
        }

        var reader = new Utf8JsonReader(Encoding.UTF8.GetBytes(text.TrimStart('\uFEFF')), new JsonReaderOptions { MaxDepth = 256 });
        long count = 0;
        try
        {
            if (!reader.Read() || reader.TokenType != JsonTokenType.StartArray)
            {
                return;
            }

            while (reader.Read() && reader.TokenType != JsonTokenType.EndArray)
            {
                if (++count > limit)
                {
                    throw new InputException(rootName, string.Create(CultureInfo.InvariantCulture, $"more than {limit} elements, the limit of {command} (docs/cli.md, Limits)"));
                }

                reader.Skip();
            }
        }
        catch (Exception e) when (e is JsonException or InvalidOperationException)
        {
            // Malformed: the parser reports where.
        }
    }
}
