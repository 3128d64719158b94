using System;
using System.IO;

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
    /// <exception cref="CliInputException">The file does not exist or cannot be read; the path is the file name as given.</exception>
    public static string Read(string file, TextReader stdin)
    {
        if (file == StandardInput)
        {
            return stdin.ReadToEnd();
        }

        try
        {
            return File.ReadAllText(file);
        }
        catch (Exception ex) when (ex is FileNotFoundException or DirectoryNotFoundException)
        {
            throw new CliInputException(file, "file not found");
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new CliInputException(file, $"cannot read file: {ex.Message}");
        }
    }
}
