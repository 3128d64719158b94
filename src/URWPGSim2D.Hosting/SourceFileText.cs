namespace URWPGSim2D.Hosting;

/// <summary>
/// Reads a strategy's source file as text whatever it was saved as: UTF-8 (with or without a byte
/// order mark) or UTF-16 with its byte order mark as such, and a file that is not valid UTF-8 as
/// GB18030, the superset of GBK (GB2312) in which Visual Studio 2008 saved Chinese sources on a
/// Chinese Windows, so that their team names and comments read as written.
/// </summary>
internal static class SourceFileText
{
    /// <summary>The code page of GB18030.</summary>
    public const int Gb18030CodePage = 54936;

    private static readonly UTF8Encoding StrictUtf8 = new(encoderShouldEmitUTF8Identifier: false, throwOnInvalidBytes: true);

    static SourceFileText() => Encoding.RegisterProvider(CodePagesEncodingProvider.Instance);

    /// <summary>The file's text, and whether it was read as GB18030 (it is not UTF-8).</summary>
    /// <param name="file">The file.</param>
    /// <exception cref="IOException">It cannot be read.</exception>
    /// <exception cref="System.UnauthorizedAccessException">It may not be read.</exception>
    public static (string Text, bool Gb18030) Read(string file) => Decode(File.ReadAllBytes(file));

    /// <summary>The text of a source file's bytes, and whether they were read as GB18030 (they are not UTF-8).</summary>
    /// <param name="bytes">The file's bytes.</param>
    public static (string Text, bool Gb18030) Decode(byte[] bytes)
    {
        if (bytes is [0xEF, 0xBB, 0xBF, ..])
        {
            return (Encoding.UTF8.GetString(bytes, 3, bytes.Length - 3), false);
        }

        if (bytes is [0xFF, 0xFE, ..])
        {
            return (Encoding.Unicode.GetString(bytes, 2, bytes.Length - 2), false);
        }

        if (bytes is [0xFE, 0xFF, ..])
        {
            return (Encoding.BigEndianUnicode.GetString(bytes, 2, bytes.Length - 2), false);
        }

        try
        {
            return (StrictUtf8.GetString(bytes), false);
        }
        catch (DecoderFallbackException)
        {
            return (Encoding.GetEncoding(Gb18030CodePage).GetString(bytes), true);
        }
    }
}
