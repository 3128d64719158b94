using URWPGSim2D.Server.Rendering;
using URWPGSim2D.Tournament.Batch;
using URWPGSim2D.Viewer;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>view TRACE.jsonl --html FILE</c>: builds the replay page of a recorded match from its trace
/// (the same page <c>run --html</c> writes). A trace the viewer cannot use — not JSON Lines, no
/// layout on its first line (an older trace), a missing field, cycles out of order — is one line
/// on stderr naming the line and the field, exit code 2, and no page is written.
/// </summary>
internal sealed class ViewCommand : ICliCommand
{
    private static readonly Option<bool> HelpOption = CliSyntax.Help();
    private static readonly Option<string> HtmlOption = CliSyntax.Value("--html", "FILE", "the replay page to write", CliCompletions.Paths);
    private static readonly Option<bool> ForceOption = CliSyntax.Flag("--force", "replace an existing --html file");

    /// <inheritdoc/>
    public Command Syntax { get; } = CliSyntax.Command("view", "Build the replay page of a match from its trace.", Line, HelpOption);

    private static readonly UsageLine Line = new(CliSyntax.Positional("TRACE.jsonl", "the match's trace (run --trace)", CliCompletions.Paths), HtmlOption, UsageLine.Optional(ForceOption));

    private static string Usage => "view " + Line.Text;

    /// <inheritdoc/>
    public string Name => "view";

    /// <inheritdoc/>
    public string Synopsis => Usage;

    /// <inheritdoc/>
    public string Summary => "Build the self-contained replay page (HTML) of a match from its trace (run --trace).";

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        string? trace = null, html = null;
        bool force = false;
        foreach (var word in words)
        {
            string a = word.Text;
            if (word.Option == HelpOption)
            {
                console.Out.Write($"Usage: {CliApp.ProgramName} {Usage}\n\n{Summary}\nThe page plays the match in any browser, offline: docs/viewer.md.\n");
                return ExitCodes.Success;
            }

            if (word.Option == HtmlOption)
            {
                if (html is not null || word.Value is null)
                {
                    throw UsageError(html is null ? "--html needs a value" : "--html given twice");
                }

                html = word.Value;
            }
            else if (word.Option == ForceOption)
            {
                force = !force ? true : throw UsageError("--force given twice");
            }
            else if (a.StartsWith("--", StringComparison.Ordinal) && a != "-")
            {
                throw CliUsageException.UnknownOption("view", a, Syntax, CliApp.ProgramName + " " + Usage);
            }
            else if (trace is null)
            {
                trace = a;
            }
            else
            {
                throw UsageError($"unexpected argument {MessageText.Quote(a)} (one TRACE file)");
            }
        }

        if (trace is null || html is null)
        {
            throw UsageError(trace is null ? "expected a TRACE file" : "expected --html FILE");
        }

        OutputFile.CheckNew("--html", html, force);
        var replay = new ReplayRecorder();
        int lineNumber = 0;
        try
        {
            using var reader = trace == "-" ? console.In : new StreamReader(trace, Encoding.UTF8);
            while (reader.ReadLine() is { } line)
            {
                lineNumber++;
                if (line.Length == 0)
                {
                    continue;
                }

                replay.Add(Encoding.UTF8.GetBytes(line));
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new InputException(trace, $"cannot read the trace ({e.Message})");
        }
        catch (TraceFormatException e)
        {
            throw new InputException($"{trace}:{lineNumber}", e.Message);
        }

        if (replay.Count == 0)
        {
            throw new InputException(trace, "the trace has no cycle line");
        }

        AtomicFile.WriteAllText(html, ReplayPage.Replay(replay.ToJson()));
        console.Out.WriteLine($"{html}: {replay.Count} cycles");
        return ExitCodes.Success;
    }

    private static CliUsageException UsageError(string message) => new("view: " + message, CliApp.ProgramName + " " + Usage);
}
