using System.IO;
using Mono.Cecil;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>
/// Answers Mono.Cecil's questions about the assemblies an old image references without any of the
/// files it was built against: the .NET Framework 2.0–3.5 assemblies (<c>mscorlib</c>, <c>System</c>,
/// <c>System.Core</c>, <c>System.Xml</c>, <c>System.Drawing</c>, …, whatever their version) are read from
/// the running runtime's own folder, where the same names stand as facades forwarding to today's types;
/// the original's assemblies and XNA (<see cref="OriginalReferences"/>) are the compatibility assembly.
/// Anything else is not resolved. Cecil asks only when it must look into another assembly (an enum
/// argument of an attribute it decodes, a forwarded type); the definitions read are kept until disposal.
/// </summary>
internal sealed class RuntimeAssemblyResolver : IAssemblyResolver
{
    private readonly Dictionary<string, AssemblyDefinition> _read = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The folder of the running runtime's assemblies (empty when the process has no files, as in a single-file build).</summary>
    public static string RuntimeDirectory { get; } = Path.GetDirectoryName(typeof(object).Assembly.Location) ?? string.Empty;

    /// <summary>The file that stands for <paramref name="name"/> here, or null when there is none.</summary>
    /// <param name="name">A simple assembly name.</param>
    public static string? FileOf(string name)
    {
        if (OriginalReferences.IsOriginal(name) || string.Equals(name, OriginalReferences.Compat.Name, StringComparison.OrdinalIgnoreCase))
        {
            string compat = typeof(RuntimeAssemblyResolver).Assembly.Location;
            return compat.Length == 0 ? null : compat;
        }

        if (RuntimeDirectory.Length == 0 || name.IndexOfAny(Path.GetInvalidFileNameChars()) >= 0 || name.Contains("..", StringComparison.Ordinal))
        {
            return null;
        }

        string file = Path.Combine(RuntimeDirectory, name + ".dll");
        return File.Exists(file) ? file : null;
    }

    /// <inheritdoc/>
    public AssemblyDefinition Resolve(AssemblyNameReference name) => Resolve(name, new ReaderParameters(ReadingMode.Deferred));

    /// <inheritdoc/>
    public AssemblyDefinition Resolve(AssemblyNameReference name, ReaderParameters parameters)
    {
        ArgumentNullException.ThrowIfNull(name);
        string? file = FileOf(name.Name) ?? throw new AssemblyResolutionException(name);
        if (!_read.TryGetValue(file, out var assembly))
        {
            assembly = AssemblyDefinition.ReadAssembly(file, new ReaderParameters(ReadingMode.Deferred)
            {
                AssemblyResolver = this,
                ReadSymbols = false,
            });
            _read.Add(file, assembly);
        }

        return assembly;
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        foreach (var assembly in _read.Values)
        {
            assembly.Dispose();
        }

        _read.Clear();
    }
}
