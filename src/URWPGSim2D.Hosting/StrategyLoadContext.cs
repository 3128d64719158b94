using System.Diagnostics.CodeAnalysis;
using System.Reflection;
using System.Runtime.Loader;

namespace URWPGSim2D.Hosting;

/// <summary>
/// The collectible AssemblyLoadContext of one team's strategy: its own dependencies resolve from its
/// folder (its .deps.json), while the SDK, the compatibility assembly, the collision library and the
/// server are shared with the host, so <see cref="IStrategy"/> and the original's types are the same
/// types on both sides. The SDK's former assembly name, <c>URWPGSim2D.Strategy</c>, is shared too: the
/// host's assembly of that name forwards every SDK type to <c>URWPGSim2D.Strategies</c>, so a strategy
/// compiled against the former name gets the same types. Assemblies an old strategy names for the
/// original's types (<c>URWPGSim2D.Common</c>, <c>Microsoft.Xna.Framework</c>, …) resolve to the
/// compatibility assembly.
/// </summary>
internal sealed class StrategyLoadContext : AssemblyLoadContext
{
    private static readonly string[] OriginalAssemblies =
        ["URWPGSim2D.Common", "URWPGSim2D.Core", "URWPGSim2D.StrategyLoader", "URWPGSim2D.StrategyHelper", "Microsoft.Xna.Framework"];

    /// <summary>The SDK's former assembly name: type forwards to the SDK (<c>URWPGSim2D.Strategies</c>).</summary>
    internal const string FormerSdkName = "URWPGSim2D.Strategy";

    private readonly AssemblyDependencyResolver? _resolver;

    /// <summary>Creates the context of a strategy assembly file (or, with no file, of compiled sources).</summary>
    /// <param name="name">Name of the context (the strategy's spec).</param>
    /// <param name="assemblyPath">The strategy assembly whose folder resolves its dependencies, or null.</param>
    public StrategyLoadContext(string name, string? assemblyPath)
        : base($"strategy:{name}", isCollectible: true)
    {
        _resolver = assemblyPath is null ? null : new AssemblyDependencyResolver(assemblyPath);
    }

    /// <summary>Whether an assembly is one the host shares with every strategy.</summary>
    /// <param name="name">Simple assembly name.</param>
    public static bool IsShared(string? name) =>
        name == typeof(IStrategy).Assembly.GetName().Name
        || name == FormerSdkName
        || name == typeof(Compat.Adapter.OriginalStrategyAdapter).Assembly.GetName().Name
        || name == typeof(StrategyLoadContext).Assembly.GetName().Name
        || name == "URWPGSim2D.Collision";

    /// <inheritdoc/>
    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = "User strategies are loaded at run time from their own files; the server is never trimmed.")]
    protected override Assembly? Load(AssemblyName assemblyName)
    {
        string? name = assemblyName.Name;
        if (IsShared(name))
        {
            return null;
        }

        if (Array.IndexOf(OriginalAssemblies, name) >= 0)
        {
            return typeof(Compat.Adapter.OriginalStrategyAdapter).Assembly;
        }

        string? path = _resolver?.ResolveAssemblyToPath(assemblyName);
        return path is null || !File.Exists(path) ? null : LoadFromAssemblyPath(path);
    }
}
