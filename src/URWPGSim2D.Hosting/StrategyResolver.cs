using System.Collections.Concurrent;
using System.Diagnostics.CodeAnalysis;
using System.Reflection;
using OriginalStrategy = global::URWPGSim2D.StrategyLoader.IStrategy;
using URWPGSim2D.Compat.Adapter;
using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Messages;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Creates a team's strategy from <c>--strategy TEAM=SPEC</c>. SPEC is a built-in name
/// (<c>idle</c>, <c>chase-ball</c>), a compiled assembly (<c>path/My.dll</c>, optionally
/// <c>#Namespace.Type</c>), a C# source file (<c>path/Strategy.cs</c>) or a folder of sources. Sources are
/// compiled in a limited child process (<see cref="CompilerProcess"/>; a strategy host compiles in its own). Every assembly gets its own collectible
/// <see cref="StrategyLoadContext"/>. An assembly may implement either API: the SDK's
/// <see cref="IStrategy"/>, or the original's <c>URWPGSim2D.StrategyLoader.IStrategy</c> (the class
/// <c>URWPGSim2D.Strategy.Strategy</c> is preferred), which runs through <see cref="OriginalStrategyAdapter"/>.
/// Failures throw <see cref="StrategyLoadException"/>.
/// </summary>
public static class StrategyResolver
{
    private const string Justification = "User strategies are loaded at run time from their own files; the server is never trimmed.";

    // The retargeted image of an old DLL written for hosts, by the SHA-256 of the DLL's bytes.
    private static readonly ConcurrentDictionary<string, string> RetargetedFiles = new(StringComparer.Ordinal);

    /// <summary>The names accepted as built-in strategies.</summary>
    public static IReadOnlyList<string> BuiltInNames { get; } = ["idle", "chase-ball"];

    /// <summary>Creates the strategy named by <paramref name="spec"/>.</summary>
    /// <param name="spec">The spec.</param>
    /// <param name="progress">Told when sources start and finish compiling (<see cref="CompiledImages.Get"/>).</param>
    /// <param name="settings">The limits of the compiler's child process (null: the defaults).</param>
    /// <param name="compileInThisProcess">Compile sources in this process (a strategy host, a remote client), not in a child.</param>
    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    public static IStrategy Load(string spec, Action<string>? progress = null, HostSettings? settings = null, bool compileInThisProcess = false)
    {
        if (spec == "idle")
        {
            return new IdleStrategy();
        }

        if (spec == "chase-ball")
        {
            return new ChaseBallStrategy();
        }

        (string path, string? typeName) = Split(spec);
        if (IsSources(path))
        {
            return FromSources(path, typeName, progress, settings, compileInThisProcess);
        }

        string full = CheckAssembly(spec, path);
        return Create(LoadAssembly(new StrategyLoadContext(path, full), path, full), path, typeName);
    }

    /// <summary>
    /// Readies the strategy named by <paramref name="spec"/> for strategy hosts without running any of
    /// its code: sources are compiled (once per run) to a file of the run's folder, and the assembly's
    /// strategy class is looked up. Null for a built-in name (built-ins run in the server's process).
    /// </summary>
    /// <param name="spec">The spec.</param>
    /// <param name="progress">Told when sources start and finish compiling (<see cref="CompiledImages.Get"/>).</param>
    /// <param name="settings">The limits of the compiler's child process (null: the defaults).</param>
    /// <exception cref="StrategyLoadException">The strategy cannot be used (same messages as <see cref="Load"/>).</exception>
    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    public static PreparedStrategy? Prepare(string spec, Action<string>? progress = null, HostSettings? settings = null)
    {
        if (spec is "idle" or "chase-ball")
        {
            return null;
        }

        (string path, string? typeName) = Split(spec);
        string suffix = typeName is null ? "" : "#" + typeName;
        if (IsSources(path))
        {
            var files = Sources(path);
            byte[] image = CompiledImages.Get(path, files, progress, settings);
            var context = new StrategyLoadContext(path, null);
            try
            {
                using var stream = new MemoryStream(image, writable: false);
                FindType(context.LoadFromStream(stream), path, typeName);
            }
            finally
            {
                context.Unload();
            }

            string dll = CompiledImages.File(path, files, settings: settings);
            return new PreparedStrategy(dll + suffix, [Path.GetDirectoryName(dll)!, Path.GetFullPath(path)]);
        }

        string full = CheckAssembly(spec, path);
        var check = new StrategyLoadContext(path, full);
        try
        {
            FindType(LoadAssembly(check, path, full), path, typeName);
        }
        finally
        {
            check.Unload();
        }

        // A DLL built for the original: hosts load its retargeted image, written once per content to the run's folder.
        var loadable = Compat.Retargeting.OriginalAssemblyLoader.Read(full);
        if (loadable.Retargeted is { } retargeted)
        {
            string file = RetargetedFiles.GetOrAdd(loadable.Sha256, _ =>
            {
                string written = Path.Combine(RunFolder.NewStrategyFolder(), Path.GetFileName(full));
                File.WriteAllBytes(written, retargeted);
                return written;
            });
            return new PreparedStrategy(file + suffix, [Path.GetDirectoryName(file)!, Path.GetDirectoryName(full)!]);
        }

        return new PreparedStrategy(full + suffix, [Path.GetDirectoryName(full)!]);
    }

    // SPEC = PATH or PATH#Type.
    private static (string Path, string? TypeName) Split(string spec)
    {
        int hash = spec.LastIndexOf('#');
        bool typed = hash > 0 && (spec[..hash].EndsWith(".dll", StringComparison.OrdinalIgnoreCase)
            || spec[..hash].EndsWith(".cs", StringComparison.OrdinalIgnoreCase) || Directory.Exists(spec[..hash]));
        return typed ? (spec[..hash], spec[(hash + 1)..]) : (spec, null);
    }

    private static bool IsSources(string path) => Directory.Exists(path) || path.EndsWith(".cs", StringComparison.OrdinalIgnoreCase);

    // The full path of an existing .dll, or a load error.
    private static string CheckAssembly(string spec, string path)
    {
        if (!path.EndsWith(".dll", StringComparison.OrdinalIgnoreCase))
        {
            throw new StrategyLoadException(
                $"{CliQuote(spec)} is not a built-in strategy ({string.Join(", ", BuiltInNames)}), a .dll, a .cs file or a folder");
        }

        string full = Path.GetFullPath(path);
        if (!File.Exists(full))
        {
            throw new StrategyLoadException($"strategy assembly not found: {path}");
        }

        return full;
    }

    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    private static Assembly LoadAssembly(StrategyLoadContext context, string path, string full)
    {
        try
        {
            return Compat.Retargeting.OriginalAssemblyLoader.Load(context, full);
        }
        catch (Exception e) when (e is BadImageFormatException or FileLoadException or IOException)
        {
            throw new StrategyLoadException($"cannot load strategy assembly {path}: {e.Message}");
        }
    }

    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    private static IStrategy FromSources(string path, string? typeName, Action<string>? progress, HostSettings? settings, bool inThisProcess)
    {
        byte[] image = CompiledImages.Get(path, Sources(path), progress, settings, inThisProcess);
        var context = new StrategyLoadContext(path, null);
        using var stream = new MemoryStream(image, writable: false);
        return Create(context.LoadFromStream(stream), path, typeName);
    }

    // The .cs files of a folder or file spec.
    private static List<string> Sources(string path)
    {
        if (!Directory.Exists(path) && !File.Exists(path))
        {
            throw new StrategyLoadException($"strategy source not found: {path}");
        }

        List<string> files;
        try
        {
            files = StrategyCompiler.SourceFiles(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new StrategyLoadException($"cannot list {path}: {e.Message}");
        }

        if (files.Count == 0)
        {
            throw new StrategyLoadException($"no .cs files in {path}");
        }

        return files;
    }

    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    [UnconditionalSuppressMessage("Trimming", "IL2072", Justification = Justification)]
    private static IStrategy Create(Assembly assembly, string path, string? typeName)
    {
        Type type = FindType(assembly, path, typeName);
        object instance;
        try
        {
            instance = Activator.CreateInstance(type)!;
        }
        catch (Exception e)
        {
            Exception cause = e is TargetInvocationException { InnerException: { } inner } ? inner : e;
            string why = cause is TypeInitializationException { InnerException: { } root }
                ? $"{cause.Message} ({root.GetType().Name}: {root.Message})"
                : cause.Message;
            throw new StrategyCreationException($"cannot create strategy {type.FullName} from {path}: {why}");
        }

        return instance is OriginalStrategy original ? new OriginalStrategyAdapter(original) : (IStrategy)instance;
    }

    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    [UnconditionalSuppressMessage("Trimming", "IL2075", Justification = Justification)]
    internal static Type FindType(Assembly assembly, string path, string? typeName)
    {
        Type[] exported;
        try
        {
            exported = assembly.GetExportedTypes();
        }
        catch (Exception e) when (e is ReflectionTypeLoadException or FileNotFoundException or FileLoadException or TypeLoadException)
        {
            throw new StrategyLoadException($"cannot read types of {path}: {e.Message}");
        }

        var found = new List<Type>();
        Type? original = null;
        foreach (var t in exported)
        {
            bool usable = t.IsClass && !t.IsAbstract && t.GetConstructor(Type.EmptyTypes) is not null
                && (typeof(IStrategy).IsAssignableFrom(t) || typeof(OriginalStrategy).IsAssignableFrom(t));
            if (usable && (typeName is null || t.FullName == typeName))
            {
                found.Add(t);
                if (t.FullName == "URWPGSim2D.Strategy.Strategy" && typeof(OriginalStrategy).IsAssignableFrom(t))
                {
                    original = t;
                }
            }
        }

        if (typeName is null && original is not null)
        {
            return original;
        }

        if (found.Count == 1)
        {
            return found[0];
        }

        if (found.Count == 0)
        {
            throw new StrategyLoadException(typeName is null
                ? $"{path} has no public strategy class (IStrategy of URWPGSim2D.Strategies or URWPGSim2D.StrategyLoader) with a parameterless constructor"
                : $"{path} has no public strategy class {typeName}");
        }

        found.Sort((a, b) => string.CompareOrdinal(a.FullName, b.FullName));
        var names = new List<string>();
        foreach (var t in found)
        {
            names.Add(t.FullName!);
        }

        throw new StrategyLoadException($"{path} has several strategy classes ({string.Join(", ", names)}): pick one with {path}#TypeName");
    }

    private static string CliQuote(string value) => MessageText.Quote(value);
}
