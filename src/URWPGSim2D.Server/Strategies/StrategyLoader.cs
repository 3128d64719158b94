using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.IO;
using System.Reflection;

namespace URWPGSim2D.Server.Strategies;

/// <summary>
/// Loads a user strategy from a compiled assembly in its own <see cref="StrategyLoadContext"/>:
/// <c>path/My.dll</c> takes the assembly's only public <see cref="IStrategy"/> class,
/// <c>path/My.dll#Namespace.Type</c> picks one. Failures throw <see cref="StrategyLoadException"/>
/// with a one-line message.
/// </summary>
internal static class StrategyLoader
{
    private const string Justification = "User strategies are loaded at run time from their own files; the server is never trimmed.";

    /// <summary>Creates the strategy named by <paramref name="spec"/>.</summary>
    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    [UnconditionalSuppressMessage("Trimming", "IL2072", Justification = Justification)]
    public static IStrategy Load(string spec)
    {
        int hash = spec.LastIndexOf('#');
        string path = hash >= 0 ? spec[..hash] : spec;
        string? typeName = hash >= 0 ? spec[(hash + 1)..] : null;
        string full = Path.GetFullPath(path);
        if (!File.Exists(full))
        {
            throw new StrategyLoadException($"strategy assembly not found: {path}");
        }

        Assembly assembly;
        try
        {
            assembly = new StrategyLoadContext(full).LoadFromAssemblyPath(full);
        }
        catch (Exception e) when (e is BadImageFormatException or FileLoadException or IOException)
        {
            throw new StrategyLoadException($"cannot load strategy assembly {path}: {e.Message}");
        }

        Type type = FindType(assembly, path, typeName);
        try
        {
            return (IStrategy)Activator.CreateInstance(type)!;
        }
        catch (Exception e)
        {
            string why = e is TargetInvocationException { InnerException: { } inner } ? inner.Message : e.Message;
            throw new StrategyLoadException($"cannot create strategy {type.FullName} from {path}: {why}");
        }
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
        catch (Exception e) when (e is ReflectionTypeLoadException or FileNotFoundException or FileLoadException)
        {
            throw new StrategyLoadException($"cannot read types of {path}: {e.Message}");
        }

        var found = new List<Type>();
        foreach (var t in exported)
        {
            if (t.IsClass && !t.IsAbstract && typeof(IStrategy).IsAssignableFrom(t) && t.GetConstructor(Type.EmptyTypes) is not null
                && (typeName is null || t.FullName == typeName))
            {
                found.Add(t);
            }
        }

        if (found.Count == 1)
        {
            return found[0];
        }

        if (found.Count == 0)
        {
            throw new StrategyLoadException(typeName is null
                ? $"{path} has no public IStrategy class with a parameterless constructor"
                : $"{path} has no public IStrategy class {typeName}");
        }

        found.Sort((a, b) => string.CompareOrdinal(a.FullName, b.FullName));
        var names = new List<string>();
        foreach (var t in found)
        {
            names.Add(t.FullName!);
        }

        throw new StrategyLoadException($"{path} has several IStrategy classes ({string.Join(", ", names)}): pick one with {path}#TypeName");
    }
}
