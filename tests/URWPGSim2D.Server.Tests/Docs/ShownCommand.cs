using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// A command of the server as a page shows it in a code block: a line <c>urwpgsim2d ARGS</c> or
/// <c>dotnet run [-c CONFIG] --project src/URWPGSim2D.Server [-- ARGS]</c>, optionally after
/// <c>$ </c> (a transcript that is not run, see <see cref="DocsOutputsTests.RunsForReal"/>) and before a
/// <c># comment</c>. Only the words are read: the command
/// (the first word when it is not an option; else <c>run</c>, the default) and the options.
/// </summary>
internal sealed partial record ShownCommand(string Where, string Line, string Command, IReadOnlyList<string> Arguments)
{
    /// <summary>The server's commands shown in a page's code blocks.</summary>
    public static IEnumerable<ShownCommand> In(string file)
    {
        foreach (var block in MarkdownBlock.Read(file))
        {
            if (DocsOutputsTests.RunsForReal(block))
            {
                continue; // a transcript DocsOutputsTests runs: its commands run as shown (some show an error on purpose)
            }

            string[] lines = block.Text.Split('\n');
            for (int i = 0; i < lines.Length; i++)
            {
                if (Of($"{file}:{block.Line + i + 1}", lines[i]) is { } shown)
                {
                    yield return shown;
                }
            }
        }
    }

    /// <summary>The command a shown line holds (<paramref name="where"/> names the line), or null when it is not a command of the server.</summary>
    public static ShownCommand? Of(string where, string line)
    {
        if (Parse(line) is not { } words)
        {
            return null;
        }

        bool named = words.Count > 0 && !words[0].StartsWith('-');
        return new ShownCommand(where, line.Trim(), named ? words[0] : "run", named ? words[1..] : words);
    }

    /// <summary>The server's arguments of a shown line, or null when the line is not a command of the server.</summary>
    public static List<string>? Parse(string line)
    {
        string text = line.Trim();
        if (text.StartsWith("$ ", StringComparison.Ordinal))
        {
            text = text[2..];
        }

        Match match = Prefix().Match(text);
        if (!match.Success)
        {
            return null;
        }

        string rest = text[match.Length..];
        int comment = CommentStart(rest);
        return [.. ShellWords.Split(comment < 0 ? rest : rest[..comment], strict: false)];
    }

    /// <summary>The options of the command: each word starting with <c>-</c>, up to an <c>=</c>.</summary>
    public IEnumerable<string> Options()
    {
        for (int i = 0; i < Arguments.Count; i++)
        {
            string word = Arguments[i];
            if (i > 0 && Arguments[i - 1] == "--sbatch-arg")
            {
                continue; // passed to sbatch as written: sbatch's option, not the server's
            }

            if (word.StartsWith('-') && word != "-")
            {
                int equals = word.IndexOf('=', StringComparison.Ordinal);
                yield return equals < 0 ? word : word[..equals];
            }
        }
    }

    /// <summary>The value after an option, or null.</summary>
    public string? ValueOf(string option)
    {
        for (int i = 0; i + 1 < Arguments.Count; i++)
        {
            if (Arguments[i] == option)
            {
                return Arguments[i + 1];
            }
        }

        return null;
    }

    // "urwpgsim2d" or "dotnet run [-c X] --project src/URWPGSim2D.Server" then " -- " (or the end).
    [GeneratedRegex(@"^(urwpgsim2d|URWPGSim2D\.Server|dotnet run (-c \w+ )?--project src/URWPGSim2D\.Server( --)?)(?= |$)", RegexOptions.CultureInvariant)]
    private static partial Regex Prefix();

    // A '#' after a blank, outside quotes, starts a shell comment ('My.dll#Type' is a word).
    private static int CommentStart(string text)
    {
        char quote = '\0';
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            if (quote != '\0')
            {
                quote = c == quote ? '\0' : quote;
            }
            else if (c is '\'' or '"')
            {
                quote = c;
            }
            else if (c == '#' && (i == 0 || char.IsWhiteSpace(text[i - 1])))
            {
                return i;
            }
        }

        return -1;
    }
}
