namespace URWPGSim2D.Tournament.Batch;

/// <summary>
/// Writes a whole text file or nothing: the text goes to a temporary file next to the target
/// (<c>TARGET.RANDOM.partial</c>), which is then renamed over the target. A reader never sees a
/// half-written file, and a failed write leaves the target as it was and no temporary behind.
/// </summary>
public static class AtomicFile
{
    /// <summary>Writes <paramref name="text"/> as UTF-8 without a byte-order mark.</summary>
    /// <param name="path">The target file; replaced if it exists.</param>
    /// <param name="text">The whole content.</param>
    /// <exception cref="IOException">The directory does not exist or the file cannot be written (also <see cref="UnauthorizedAccessException"/>).</exception>
    public static void WriteAllText(string path, string text)
    {
        string full = Path.GetFullPath(path);
        string temporary = $"{full}.{Path.GetRandomFileName()}.partial";
        try
        {
            File.WriteAllText(temporary, text, new UTF8Encoding(false));
            File.Move(temporary, full, overwrite: true);
        }
        catch
        {
            TryDelete(temporary);
            throw;
        }
    }

    private static void TryDelete(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            // Best effort: the original error is the one to report.
        }
    }
}
