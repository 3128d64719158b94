namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>The words of a command line as a page shows it.</summary>
internal static class ShellWords
{
    /// <summary>
    /// Splits on blanks, honouring '…' and "…" (no escapes inside, as the docs never need them).
    /// With <paramref name="strict"/>, shell syntax (pipes, redirections, globs, variables) throws
    /// <see cref="FormatException"/>: a transcript runs its words as they are.
    /// </summary>
    public static string[] Split(string text, bool strict)
    {
        var words = new List<string>();
        var word = new StringBuilder();
        bool inWord = false;
        char quote = '\0';
        foreach (char c in text)
        {
            if (quote != '\0')
            {
                if (c == quote)
                {
                    quote = '\0';
                }
                else
                {
                    word.Append(c);
                }
            }
            else if (c is '\'' or '"')
            {
                quote = c;
                inWord = true;
            }
            else if (char.IsWhiteSpace(c))
            {
                if (inWord)
                {
                    words.Add(word.ToString());
                    word.Clear();
                    inWord = false;
                }
            }
            else if (strict && c is '|' or '>' or '<' or ';' or '&' or '*' or '$')
            {
                throw new FormatException($"shell syntax the docs' transcripts do not run: {c} in {text}");
            }
            else
            {
                word.Append(c);
                inWord = true;
            }
        }

        if (inWord)
        {
            words.Add(word.ToString());
        }

        return [.. words];
    }
}
