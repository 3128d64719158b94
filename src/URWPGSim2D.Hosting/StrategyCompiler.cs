using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Compiles a team's strategy sources (Roslyn; the server runs it in a child process, <see cref="CompilerProcess"/>) against the framework, the strategy SDK and
/// the compatibility assembly (the original's API). Errors come back as <c>file(line,col): error CSnnnn:
/// message</c> lines, led by their likely cause (<see cref="CompileErrors"/>); warnings are ignored, and the ones old sources always raise on .NET 10 are
/// suppressed outright: the obsolete <c>InitializeLifetimeService</c> override (CS0672, SYSLIB0010,
/// CS0618), the lower-case <c>xna</c> alias (CS8981) and a team's own <c>StrategyHelper.cs</c> taking
/// precedence over the compatibility assembly's copy (CS0436).
/// </summary>
internal static class StrategyCompiler
{
    private static readonly string[] Suppressed = ["CS0672", "SYSLIB0010", "CS0618", "CS8981", "CS0436", "CS1701", "CS1702"];

    private static readonly Lazy<ImmutableArray<MetadataReference>> References = new(CreateReferences);

    /// <summary>The source files of a spec: the file itself, or every .cs file under a folder (bin/ and obj/ skipped), in ordinal order.</summary>
    /// <param name="spec">A .cs file or a folder, as the user wrote it.</param>
    /// <returns>The files, as paths starting with <paramref name="spec"/>.</returns>
    public static List<string> SourceFiles(string spec)
    {
        var files = new List<string>();
        if (File.Exists(spec))
        {
            files.Add(spec);
            return files;
        }

        Collect(spec, spec, files);
        files.Sort(StringComparer.Ordinal);
        return files;
    }

    // The .cs files under folder (bin/ and obj/ at the top skipped); a symbolic link that could lead
    // to sources (a .cs file or a folder) is refused: only regular files inside the folder are read.
    private static void Collect(string spec, string folder, List<string> files)
    {
        var options = new EnumerationOptions { RecurseSubdirectories = false, AttributesToSkip = 0, IgnoreInaccessible = false };
        foreach (string entry in Directory.EnumerateFileSystemEntries(folder, "*", options))
        {
            string relative = Path.GetRelativePath(spec, entry);
            if (relative is "bin" or "obj")
            {
                continue;
            }

            var info = new FileInfo(entry);
            bool source = entry.EndsWith(".cs", OperatingSystem.IsLinux() ? StringComparison.Ordinal : StringComparison.OrdinalIgnoreCase);
            if (info.LinkTarget is not null)
            {
                if (source || Directory.Exists(entry))
                {
                    throw new StrategyLoadException($"{Path.Combine(spec, relative)} is a symbolic link: only regular files inside the strategy's folder are read");
                }

                continue;
            }

            if (info.Attributes.HasFlag(FileAttributes.Directory))
            {
                Collect(spec, entry, files);
            }
            else if (source)
            {
                files.Add(Path.Combine(spec, relative));
            }
        }
    }

    /// <summary>Compiles the files into an assembly image.</summary>
    /// <param name="name">Assembly name.</param>
    /// <param name="files">The source files.</param>
    /// <param name="note">Told one line for each file that is not UTF-8 and was read as GB18030 (<see cref="SourceFileText"/>).</param>
    /// <returns>The assembly image.</returns>
    /// <param name="readFrom">Where each file is read from when not from its name (the same count), or null.</param>
    /// <exception cref="StrategyLoadException">A file cannot be read, or the sources do not compile (<see cref="CompileErrors"/>).</exception>
    public static byte[] Compile(string name, IReadOnlyList<string> files, Action<string>? note = null, IReadOnlyList<string>? readFrom = null)
    {
        var trees = new List<SyntaxTree>(files.Count);
        var parse = new CSharpParseOptions(LanguageVersion.Latest);
        for (int i = 0; i < files.Count; i++)
        {
            string file = files[i];
            string text;
            try
            {
                (text, bool gb18030) = SourceFileText.Read(readFrom is null ? file : readFrom[i]);
                if (gb18030)
                {
                    note?.Invoke($"{file} is not UTF-8: read as GB18030 (GBK, as Visual Studio 2008 saved Chinese sources); save it as UTF-8 to be sure");
                }
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                throw new StrategyLoadException($"cannot read {file}: {e.Message}");
            }

            trees.Add(CSharpSyntaxTree.ParseText(text, parse, file, Encoding.UTF8));
        }

        var options = new CSharpCompilationOptions(
            OutputKind.DynamicallyLinkedLibrary,
            optimizationLevel: OptimizationLevel.Release,
            allowUnsafe: true,
            nullableContextOptions: NullableContextOptions.Disable,
            specificDiagnosticOptions: Suppress());
        var compilation = CSharpCompilation.Create(name, trees, References.Value, options);
        using var image = new MemoryStream();
        var result = compilation.Emit(image);
        if (!result.Success)
        {
            var (message, details) = CompileErrors.Report(compilation, result.Diagnostics, files.Count);
            throw new StrategyLoadException(message, details);
        }

        return image.ToArray();
    }

    /// <summary>One diagnostic as <c>file(line,col): error ID: message</c> (1-based line and column).</summary>
    public static string Format(Diagnostic d)
    {
        var span = d.Location.GetLineSpan();
        string where = span.IsValid
            ? string.Create(CultureInfo.InvariantCulture, $"{span.Path}({span.StartLinePosition.Line + 1},{span.StartLinePosition.Character + 1})")
            : "(no file)";
        string message = d.GetMessage(CultureInfo.InvariantCulture).Replace('\n', ' ').Replace('\r', ' ');
        return string.Create(CultureInfo.InvariantCulture, $"{where}: error {d.Id}: {message}");
    }

    private static ImmutableDictionary<string, ReportDiagnostic> Suppress()
    {
        var b = ImmutableDictionary.CreateBuilder<string, ReportDiagnostic>();
        foreach (string id in Suppressed)
        {
            b[id] = ReportDiagnostic.Suppress;
        }

        return b.ToImmutable();
    }

    // The framework's own assemblies (from the trusted platform list, in the runtime's folder) plus the SDK, the collision library under it and the compatibility assembly.
    [UnconditionalSuppressMessage("SingleFile", "IL3000", Justification = "The server runs from its own folder (never a single-file bundle): assemblies have paths.")]
    private static ImmutableArray<MetadataReference> CreateReferences()
    {
        var list = ImmutableArray.CreateBuilder<MetadataReference>();
        string runtime = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
        string trusted = AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES") as string ?? string.Empty;
        foreach (string path in trusted.Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
        {
            if (string.Equals(Path.GetDirectoryName(path), runtime, StringComparison.Ordinal))
            {
                list.Add(MetadataReference.CreateFromFile(path));
            }
        }

        list.Add(MetadataReference.CreateFromFile(typeof(IStrategy).Assembly.Location));
        list.Add(MetadataReference.CreateFromFile(typeof(Collision.Queries.ShapeQuery).Assembly.Location)); // the SDK's FieldSensor answers in its types
        list.Add(MetadataReference.CreateFromFile(typeof(Compat.Adapter.OriginalStrategyAdapter).Assembly.Location));
        return list.ToImmutable();
    }
}
