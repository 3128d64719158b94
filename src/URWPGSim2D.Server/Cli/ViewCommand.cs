using System;
using System.IO;
using System.Text;
using URWPGSim2D.Server.Json;
using URWPGSim2D.Server.Rendering;
using URWPGSim2D.Server.Viewer;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>view TRACE.jsonl --html FILE</c>: builds the replay page of a recorded match from its trace
/// (the same page <c>run --html</c> writes). A trace the viewer cannot use — not JSON Lines, no
/// layout on its first line (an older trace), a missing field, cycles out of order — is one line
/// on stderr naming the line and the field, exit code 2, and no page is written.
/// </summary>
internal sealed class ViewCommand : ICliCommand
{
    private const string Usage = "view TRACE.jsonl --html FILE [--force]";

    /// <inheritdoc/>
    public string Name => "view";

    /// <inheritdoc/>
    public string Synopsis => Usage;

    /// <inheritdoc/>
    public string Summary => "Build the self-contained replay page (HTML) of a match from its trace (run --trace).";

    /// <inheritdoc/>
    public int Run(ReadOnlySpan<string> arguments, CliConsole console)
    {
        string? trace = null, html = null;
        bool force = false;
        for (int i = 0; i < arguments.Length; i++)
        {
            string a = arguments[i];
            if (CliApp.IsHelp(a))
            {
                console.Out.Write($"Usage: {CliApp.ProgramName} {Usage}\n\n{Summary}\nThe page plays the match in any browser, offline: docs/viewer.md.\n");
                return ExitCodes.Success;
            }

            if (a == "--html")
            {
                if (html is not null || i + 1 >= arguments.Length)
                {
                    throw UsageError(html is null ? "--html needs a value" : "--html given twice");
                }

                html = arguments[++i];
            }
            else if (a == "--force")
            {
                force = !force ? true : throw UsageError("--force given twice");
            }
            else if (a.StartsWith("--", StringComparison.Ordinal) && a != "-")
            {
                throw CliUsageException.UnknownOption("view", a, CliApp.ProgramName + " " + Usage);
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
