using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// A command transcript of the docs: a code block whose first line starts with <c>$ </c>. Each
/// <c>$</c> line is a command (continued on the next lines while a quote is open), the lines up to
/// the next <c>$</c> line are what it prints (stdout, then stderr); <c>$ echo $?</c> prints the
/// previous command's exit code. The commands understood:
/// <c>urwpgsim2d ARGS</c> (the tool's command; the docs call the program by no other name),
/// <c>dotnet run -c Release --project src/URWPGSim2D.Server -- ARGS</c>, each optionally after
/// <c>echo 'TEXT' |</c> (TEXT on standard input). Run from the repository root.
/// </summary>
internal sealed partial record Transcript(IReadOnlyList<Transcript.Step> Steps)
{
    private static readonly string[] ServerPrefixes = ["urwpgsim2d", "dotnet run -c Release --project src/URWPGSim2D.Server --"];

    /// <summary>One command and what the docs say it prints.</summary>
    /// <param name="Command">The command text as shown (without <c>$ </c>; may span lines).</param>
    /// <param name="Arguments">The server's arguments, or null for <c>echo $?</c>.</param>
    /// <param name="Stdin">Standard input (from <c>echo '…' |</c>), or empty.</param>
    /// <param name="Expected">The lines shown after the command.</param>
    internal sealed record Step(string Command, string[]? Arguments, string Stdin, IReadOnlyList<string> Expected);

    /// <summary>Reads a block's text as a transcript; a command it cannot run throws <see cref="FormatException"/>.</summary>
    public static Transcript Parse(string text)
    {
        string[] lines = text.Split('\n');
        var steps = new List<Step>();
        int i = 0;
        while (i < lines.Length)
        {
            if (!lines[i].StartsWith("$ ", StringComparison.Ordinal))
            {
                throw new FormatException($"line {i + 1} of the block is neither a command nor its output");
            }

            var command = new StringBuilder(lines[i][2..]);
            while (OpenQuote(command.ToString()) && ++i < lines.Length)
            {
                command.Append('\n').Append(lines[i]);
            }

            i++;
            var expected = new List<string>();
            while (i < lines.Length && !lines[i].StartsWith("$ ", StringComparison.Ordinal))
            {
                expected.Add(lines[i++]);
            }

            string shown = command.ToString();
            if (shown == "echo $?")
            {
                steps.Add(new Step(shown, null, string.Empty, expected));
                continue;
            }

            var (arguments, stdin) = Command(shown);
            steps.Add(new Step(shown, arguments, stdin, expected));
        }

        return new Transcript(steps);
    }

    /// <summary>
    /// Timing figures, the one part of an output that differs from run to run, made equal: wall
    /// times, and the late calls a busy machine may cause, whose overrun the time bank pays without
    /// changing the match (a spent bank, which does change it, stays as it is).
    /// </summary>
    public static string Mask(string output)
    {
        output = MatchTiming().Replace(output, "in <T> wall time (<T>x real time, <T> us per cycle)");
        output = LateCalls().Replace(output, "for late calls: <T>");
        output = CompileTiming().Replace(output, "$1 in <T> s");
        return BatchTiming().Replace(output, "wall time: <T> s on <T> threads, <T> matches/s, <T>x real time");
    }

    /// <summary>Whether an output shown in the docs is <paramref name="actual"/>: equal once masked, a shown <c> ... </c> standing for any text.</summary>
    public static bool Matches(string shown, string actual)
    {
        string[] pieces = Mask(shown).Split(" ... ");
        string pattern = "^" + string.Join(".*", pieces.Select(Regex.Escape)) + "$";
        return Regex.IsMatch(Mask(actual), pattern, RegexOptions.Singleline | RegexOptions.CultureInvariant, TimeSpan.FromSeconds(10));
    }

    [GeneratedRegex(@"in [0-9.]+ ms wall time \([0-9.]+x real time, [0-9.]+ us per cycle\)")]
    private static partial Regex MatchTiming();

    [GeneratedRegex(@"for late calls:(?: none drawn|(?:\n  team [0-9]+ \([^\n]*\): [0-9]+ late calls?, [0-9.]+ s drawn, slowest call [0-9]+ ms)+)(?=\n|$)")]
    private static partial Regex LateCalls();

    [GeneratedRegex(@"^(compiled [^\n]+) in [0-9.]+ s$", RegexOptions.Multiline)]
    private static partial Regex CompileTiming();

    [GeneratedRegex(@"wall time: [0-9.]+ s on [0-9]+ threads, [0-9.]+ matches/s, [0-9.]+x real time")]
    private static partial Regex BatchTiming();

    private static (string[] Arguments, string Stdin) Command(string shown)
    {
        string stdin = string.Empty;
        string rest = shown;
        if (rest.StartsWith("echo '", StringComparison.Ordinal))
        {
            int close = rest.IndexOf('\'', 6);
            string after = close < 0 ? string.Empty : rest[(close + 1)..].TrimStart();
            if (close < 0 || !after.StartsWith('|'))
            {
                throw new FormatException($"expected echo 'TEXT' | COMMAND, got: {shown}");
            }

            stdin = rest[6..close] + "\n";
            rest = after[1..].TrimStart();
        }

        string? prefix = ServerPrefixes.FirstOrDefault(p => rest == p || rest.StartsWith(p + " ", StringComparison.Ordinal));
        if (prefix is null)
        {
            throw new FormatException($"not a command of the server: {shown}");
        }

        return (ShellWords.Split(rest[prefix.Length..], strict: true), stdin);
    }

    private static bool OpenQuote(string text) => text.Count(c => c == '\'') % 2 == 1;
}
