using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.IO;
using System.Reflection;
using URWPGSim2D.Compat.Hosting;
using OriginalStrategy = global::URWPGSim2D.StrategyLoader.IStrategy;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// Creates a team's strategy from <c>--strategy TEAM=SPEC</c>. SPEC is a built-in name
/// (<c>idle</c>, <c>chase-ball</c>), a compiled assembly (<c>path/My.dll</c>, optionally
/// <c>#Namespace.Type</c>), a C# source file (<c>path/Strategy.cs</c>) or a folder of sources. Sources are
/// compiled in process (<see cref="StrategyCompiler"/>). Every assembly gets its own collectible
/// <see cref="StrategyLoadContext"/>. An assembly may implement either API: the SDK's
/// <see cref="IStrategy"/>, or the original's <c>URWPGSim2D.StrategyLoader.IStrategy</c> (the class
/// <c>URWPGSim2D.Strategy.Strategy</c> is preferred), which runs through <see cref="OriginalStrategyAdapter"/>.
/// Failures throw <see cref="StrategyLoadException"/>.
/// </summary>
internal static class StrategyResolver
{
    private const string Justification = "User strategies are loaded at run time from their own files; the server is never trimmed.";

    /// <summary>The names accepted as built-in strategies.</summary>
    public static IReadOnlyList<string> BuiltInNames { get; } = ["idle", "chase-ball"];

    /// <summary>Creates the strategy named by <paramref name="spec"/>.</summary>
    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    public static IStrategy Load(string spec)
    {
        if (spec == "idle")
        {
            return new IdleStrategy();
        }

        if (spec == "chase-ball")
        {
            return new ChaseBallStrategy();
        }

        int hash = spec.LastIndexOf('#');
        bool typed = hash > 0 && (spec[..hash].EndsWith(".dll", StringComparison.OrdinalIgnoreCase)
            || spec[..hash].EndsWith(".cs", StringComparison.OrdinalIgnoreCase) || Directory.Exists(spec[..hash]));
        string path = typed ? spec[..hash] : spec;
        string? typeName = typed ? spec[(hash + 1)..] : null;
        if (Directory.Exists(path) || path.EndsWith(".cs", StringComparison.OrdinalIgnoreCase))
        {
            return FromSources(path, typeName);
        }

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

        Assembly assembly;
        try
        {
            assembly = Compat.Retargeting.OriginalAssemblyLoader.Load(new StrategyLoadContext(path, full), full);
        }
        catch (Exception e) when (e is BadImageFormatException or FileLoadException or IOException)
        {
            throw new StrategyLoadException($"cannot load strategy assembly {path}: {e.Message}");
        }

        return Create(assembly, path, typeName);
    }

    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    private static IStrategy FromSources(string path, string? typeName)
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

        string name = "Strategy_" + Path.GetFileNameWithoutExtension(Path.TrimEndingDirectorySeparator(path));
        byte[] image;
        try
        {
            image = StrategyCompiler.Compile(name, files);
        }
        catch (StrategyLoadException e)
        {
            throw new StrategyLoadException($"cannot compile {path}: {e.Message}", e.Details);
        }

        var context = new StrategyLoadContext(path, null);
        using var stream = new MemoryStream(image, writable: false);
        return Create(context.LoadFromStream(stream), path, typeName);
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
            string why = e is TargetInvocationException { InnerException: { } inner } ? inner.Message : e.Message;
            throw new StrategyLoadException($"cannot create strategy {type.FullName} from {path}: {why}");
        }

        return instance is OriginalStrategy original ? new OriginalStrategyAdapter(original) : (IStrategy)instance;
    }

    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    [UnconditionalSuppressMessage("Trimming", "IL2075", Justification = Justification)]
    private static Type FindType(Assembly assembly, string path, string? typeName)
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

    private static string CliQuote(string value) => Cli.CliText.Quote(value);
}
