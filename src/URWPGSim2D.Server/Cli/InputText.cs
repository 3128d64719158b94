namespace URWPGSim2D.Server.Cli;

/// <summary>Reads a command's whole input: a file, or standard input when the argument is <c>-</c>.</summary>
internal static class InputText
{
    /// <summary>The argument that stands for standard input.</summary>
    public const string StandardInput = "-";

    /// <summary>Reads the whole text of <paramref name="file"/> (UTF-8 unless a byte-order mark says otherwise).</summary>
    /// <param name="file">A file path, or <c>-</c> for <paramref name="stdin"/>.</param>
    /// <param name="stdin">The standard input reader.</param>
    /// <returns>The text.</returns>
    /// <exception cref="InputException">The file does not exist or cannot be read; the path is the file name as given.</exception>
    public static string Read(string file, TextReader stdin)
    {
        if (file == StandardInput)
        {
            return ReadLimited(stdin, file);
        }

        try
        {
            var info = new FileInfo(file);
            if (info.Exists && info.Length > InputLimits.InputBytes)
            {
                throw new InputException(file, InputLimits.TooLarge(info.Length));
            }

            return File.ReadAllText(file);
        }
        catch (Exception ex) when (ex is FileNotFoundException or DirectoryNotFoundException)
        {
            throw new InputException(file, "file not found");
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new InputException(file, $"cannot read file: {ex.Message}");
        }
    }

    /// <summary>Reads a reader to its end, failing once it has given more than <see cref="InputLimits.InputBytes"/> characters.</summary>
    /// <param name="reader">The input.</param>
    /// <param name="name">The input's name in the message (<c>-</c> for stdin).</param>
    /// <returns>The text.</returns>
    /// <exception cref="InputException">The input is too large.</exception>
    public static string ReadLimited(TextReader reader, string name)
    {
        var text = new StringBuilder();
        char[] buffer = new char[1 << 16];
        int read;
        while ((read = reader.Read(buffer, 0, buffer.Length)) > 0)
        {
            text.Append(buffer, 0, read);
            if (text.Length > InputLimits.InputBytes)
            {
                throw new InputException(name, $"the input is more than {InputLimits.InputBytes >> 20} Mi characters, the limit (docs/cli.md, Limits)");
            }
        }

        return text.ToString();
    }
}
