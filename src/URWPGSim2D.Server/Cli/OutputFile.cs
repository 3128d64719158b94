namespace URWPGSim2D.Server.Cli;

/// <summary>
/// Checks an output FILE option before any work starts, so a bad path is one line and exit code 2
/// up front instead of a failure after a whole match: the folder must exist and the path must not
/// be a folder. Nothing is created by the check. A results, trace or page file that exists is not
/// replaced unless the command is given <c>--force</c> (<see cref="CheckNew"/>).
/// </summary>
internal static class OutputFile
{
    /// <summary>Fails when <paramref name="path"/> cannot be an output file.</summary>
    /// <param name="option">The option that names the file, e.g. <c>--svg</c>; the start of the message.</param>
    /// <param name="path">The path given, or null when the option is absent (no check).</param>
    /// <exception cref="InputException">The folder does not exist, or the path is a folder or not a valid path.</exception>
    public static void Check(string option, string? path)
    {
        if (path is null)
        {
            return;
        }

        string full;
        try
        {
            full = Path.GetFullPath(path);
        }
        catch (System.Exception e) when (e is System.ArgumentException or System.NotSupportedException or PathTooLongException)
        {
            throw new InputException(option, $"cannot write {MessageText.Quote(path)} (not a valid path)");
        }

        if (path.Length == 0 || Directory.Exists(full))
        {
            throw new InputException(option, $"cannot write {MessageText.Quote(path)} (it is a folder, give a file name)");
        }

        string? folder = Path.GetDirectoryName(full);
        if (folder is not null && !Directory.Exists(folder))
        {
            throw new InputException(option, $"cannot write {MessageText.Quote(path)} (folder {MessageText.Quote(folder)} does not exist)");
        }
    }

    /// <summary>
    /// Fails like <see cref="Check"/>, and also when <paramref name="path"/> exists and
    /// <paramref name="force"/> is false: nothing already written is lost to a typo.
    /// </summary>
    /// <param name="option">The option that names the file, e.g. <c>--results</c>; the start of the message.</param>
    /// <param name="path">The path given, or null when the option is absent (no check).</param>
    /// <param name="force">Whether <c>--force</c> was given: an existing file is replaced.</param>
    /// <exception cref="InputException">As <see cref="Check"/>, or the file exists.</exception>
    public static void CheckNew(string option, string? path, bool force)
    {
        Check(option, path);
        if (path is not null && !force && File.Exists(path))
        {
            throw new InputException(option, $"{MessageText.Quote(path)} exists; give --force to replace it");
        }
    }
}
