namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// One fenced code block of a Markdown file: its info string (<c>csharp</c>, <c>sh</c>, …), its
/// text, its line and the HTML comment line right before the fence (the tie to a sample or a
/// golden output), if any.
/// </summary>
internal sealed record MarkdownBlock(string File, int Line, string Info, string Text, string? Marker)
{
    /// <summary>Every fenced block of a Markdown file (a path relative to the repository root).</summary>
    public static IEnumerable<MarkdownBlock> Read(string file)
    {
        string[] lines = System.IO.File.ReadAllLines(Repository.PathOf(file));
        for (int i = 0; i < lines.Length; i++)
        {
            if (!lines[i].StartsWith("```", StringComparison.Ordinal))
            {
                continue;
            }

            string info = lines[i][3..].Trim();
            int start = i + 1;
            int end = start;
            while (end < lines.Length && lines[end] != "```")
            {
                end++;
            }

            if (end == lines.Length)
            {
                throw new InvalidDataException($"{file}:{i + 1}: the code block is not closed");
            }

            string? marker = i > 0 && lines[i - 1].StartsWith("<!--", StringComparison.Ordinal) && lines[i - 1].EndsWith("-->", StringComparison.Ordinal)
                ? lines[i - 1][4..^3].Trim()
                : null;
            yield return new MarkdownBlock(file, i + 1, info, string.Join('\n', lines[start..end]), marker);
            i = end;
        }
    }

    /// <summary>The value of a marker <c>&lt;!-- NAME: VALUE --&gt;</c> with this name, else null.</summary>
    public string? MarkerValue(string name) =>
        Marker is { } m && m.StartsWith(name + ":", StringComparison.Ordinal) ? m[(name.Length + 1)..].Trim() : null;

    /// <summary>Where the block is, for messages: <c>FILE:LINE</c>.</summary>
    public string Where => $"{File}:{Line}";
}
