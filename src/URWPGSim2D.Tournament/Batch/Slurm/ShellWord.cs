using System.Buffers;

namespace URWPGSim2D.Tournament.Batch.Slurm;

/// <summary>
/// A string as one word of a POSIX shell (bash) command line: left bare when it holds only
/// characters no shell treats specially, otherwise in single quotes, where nothing is special but
/// the single quote itself, written <c>'\''</c>. Any string, spaces, quotes, <c>$</c>, backslashes
/// and line breaks included, comes back unchanged as one argument.
/// </summary>
public static class ShellWord
{
    private static readonly SearchValues<char> Plain =
        SearchValues.Create("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+./:,@%=");

    /// <summary>The shell word for <paramref name="value"/>.</summary>
    /// <param name="value">Any string.</param>
    /// <returns>E.g. <c>--batch</c>, <c>'/tmp/my results'</c> or <c>'it'\''s'</c>; <c>''</c> for the empty string.</returns>
    public static string Quote(string value)
    {
        if (value.Length > 0 && !value.AsSpan().ContainsAnyExcept(Plain) && value[0] != '=')
        {
            return value;
        }

        return "'" + value.Replace("'", "'\\''", StringComparison.Ordinal) + "'";
    }
}
