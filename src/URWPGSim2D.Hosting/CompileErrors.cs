using Microsoft.CodeAnalysis;

namespace URWPGSim2D.Hosting;

/// <summary>
/// The lines a failed strategy compilation prints. With a likely cause (<see cref="CompileCause"/>):
/// the cause first, then the first <see cref="PerFile"/> errors of each file grouped by file, then the
/// count. Without one: the count first, then the errors grouped the same way. An error line is
/// <c>file(line,col): error CSnnnn: message</c>; a file with more errors ends in one line saying how
/// many more.
/// </summary>
internal static class CompileErrors
{
    /// <summary>Errors shown per file; the rest are counted.</summary>
    public const int PerFile = 5;

    /// <summary>The message (one line) and the detail lines of a failed compilation.</summary>
    /// <param name="compilation">The compilation.</param>
    /// <param name="diagnostics">Its diagnostics (errors and others).</param>
    /// <param name="files">How many source files were compiled.</param>
    public static (string Message, List<string> Details) Report(Compilation compilation, IEnumerable<Diagnostic> diagnostics, int files)
    {
        var errors = Sorted(diagnostics);
        var c = CultureInfo.InvariantCulture;
        string count = string.Create(c, $"{errors.Count} compile error{(errors.Count == 1 ? string.Empty : "s")} in {files} file{(files == 1 ? string.Empty : "s")}");
        var details = new List<string>(errors.Count + 2);
        bool cut = false;
        for (int i = 0; i < errors.Count;)
        {
            string path = Path(errors[i]);
            int end = i;
            while (end < errors.Count && Path(errors[end]) == path)
            {
                end++;
            }

            for (int k = i; k < Math.Min(end, i + PerFile); k++)
            {
                details.Add(StrategyCompiler.Format(errors[k]));
            }

            if (end - i > PerFile)
            {
                cut = true;
                details.Add(string.Create(c, $"  ... {end - i - PerFile} more in {(path.Length > 0 ? path : "(no file)")}"));
            }

            i = end;
        }

        string? cause = CompileCause.Find(compilation, errors);
        if (cause is null)
        {
            return (count + ":", details);
        }

        details.Add(cut ? string.Create(c, $"{count} (the first {PerFile} of each file shown)") : count);
        return ("likely cause: " + cause, details);
    }

    // The errors by file, line and column.
    private static List<Diagnostic> Sorted(IEnumerable<Diagnostic> diagnostics)
    {
        var errors = new List<Diagnostic>();
        foreach (var d in diagnostics)
        {
            if (d.Severity == DiagnosticSeverity.Error)
            {
                errors.Add(d);
            }
        }

        errors.Sort((a, b) =>
        {
            var pa = a.Location.GetLineSpan();
            var pb = b.Location.GetLineSpan();
            int c = string.CompareOrdinal(pa.Path, pb.Path);
            c = c != 0 ? c : pa.StartLinePosition.Line.CompareTo(pb.StartLinePosition.Line);
            return c != 0 ? c : pa.StartLinePosition.Character.CompareTo(pb.StartLinePosition.Character);
        });
        return errors;
    }

    private static string Path(Diagnostic d) => d.Location.GetLineSpan() is { IsValid: true } span ? span.Path : string.Empty;
}
