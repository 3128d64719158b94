using System.CommandLine.Completions;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The completion request of the shell scripts (<c>completion bash</c>): System.CommandLine's
/// <c>[suggest:N]</c> directive followed by the command line as the shell has it, program name
/// first; the answer is one completion per line on stdout, exit code 0.
/// </summary>
internal static class ShellCompletion
{
    /// <summary>Whether the arguments are a completion request: <c>[suggest]</c> or <c>[suggest:N]</c> first.</summary>
    /// <param name="args">The program's arguments.</param>
    public static bool IsRequest(ReadOnlySpan<string> args) =>
        args.Length > 0 && args[0].StartsWith("[suggest", StringComparison.Ordinal) && args[0].EndsWith(']');

    /// <summary>
    /// Writes the completions of the command line <c>args[1]</c> (the program's name, then its
    /// arguments) at the cursor position <c>N</c> of <c>[suggest:N]</c> (the end of the line without one).
    /// </summary>
    /// <param name="root">The program's declared syntax.</param>
    /// <param name="args">The request.</param>
    /// <param name="console">Where the completions go.</param>
    /// <returns>0; a malformed position is bad arguments.</returns>
    public static int Answer(RootCommand root, ReadOnlySpan<string> args, CliConsole console)
    {
        ArgumentNullException.ThrowIfNull(root);
        ArgumentNullException.ThrowIfNull(console);
        string line = args.Length > 1 ? string.Join(' ', args[1..].ToArray()) : string.Empty;
        string directive = args[0];
        int position = line.Length;
        if (directive != "[suggest]"
            && (!directive.StartsWith("[suggest:", StringComparison.Ordinal)
                || !int.TryParse(directive.AsSpan(9, directive.Length - 10), NumberStyles.None, CultureInfo.InvariantCulture, out position)
                || position > line.Length))
        {
            throw new CliUsageException($"completion: the request must be [suggest:N] with N a cursor position 0..{line.Length} in the line, got {Engine.Messages.MessageText.Quote(directive)}", null);
        }

        foreach (string completion in Complete(root, line, position))
        {
            console.Out.Write(completion + "\n");
        }

        return ExitCodes.Success;
    }

    /// <summary>The completions at <paramref name="position"/> of <paramref name="line"/>, whose first word is the program.</summary>
    /// <param name="root">The program's declared syntax.</param>
    /// <param name="line">The command line, program name first.</param>
    /// <param name="position">The cursor position, 0 … the line's length.</param>
    /// <returns>The labels, in System.CommandLine's order.</returns>
    public static string[] Complete(RootCommand root, string line, int position)
    {
        ArgumentNullException.ThrowIfNull(root);
        ArgumentNullException.ThrowIfNull(line);
        int start = 0;
        while (start < line.Length && char.IsWhiteSpace(line[start]))
        {
            start++;
        }

        int end = start;
        while (end < line.Length && !char.IsWhiteSpace(line[end]))
        {
            end++;
        }

        if (position <= end)
        {
            return []; // the program's own name
        }

        string arguments = line[end..];
        ParseResult parse = root.Parse(arguments, CliSyntax.Parser);
        var labels = parse.GetCompletions(position - end).Select(c => c.Label).ToList();
        CompletionContext context = parse.GetCompletionContext();
        string word = (context is TextCompletionContext text ? text.AtCursorPosition(position - end) : context).WordToComplete;
        if (word.StartsWith('-'))
        {
            // System.CommandLine offers an option that has its value no more; an option that may be
            // given again (--strategy, --entrant, --sbatch-arg, ...) is offered again all the same.
            labels.AddRange(parse.CommandResult.Command.Options
                .Where(o => o.ValueType == typeof(string[]) && o.Name.StartsWith(word, StringComparison.Ordinal))
                .Select(o => o.Name));
        }

        return [.. labels.Distinct(StringComparer.Ordinal).Order(StringComparer.OrdinalIgnoreCase)];
    }
}
