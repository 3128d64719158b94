using System.Diagnostics.CodeAnalysis;
using System.Reflection;
using System.Runtime.Loader;

namespace URWPGSim2D.Server.Strategies;

/// <summary>
/// The AssemblyLoadContext of one user strategy assembly: its own dependencies resolve from its
/// folder (its .deps.json), while the server's and the collision library's assemblies are shared
/// with the host so that <see cref="IStrategy"/> is the same type on both sides.
/// </summary>
internal sealed class StrategyLoadContext(string assemblyPath) : AssemblyLoadContext($"strategy:{assemblyPath}")
{
    private readonly AssemblyDependencyResolver _resolver = new(assemblyPath);

    /// <inheritdoc/>
    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = "User strategies are loaded at run time from their own files; the server is never trimmed.")]
    protected override Assembly? Load(AssemblyName assemblyName)
    {
        string? name = assemblyName.Name;
        if (name == typeof(IStrategy).Assembly.GetName().Name || name == typeof(StrategyLoadContext).Assembly.GetName().Name || name == "URWPGSim2D.Collision")
        {
            return null;
        }

        string? path = _resolver.ResolveAssemblyToPath(assemblyName);
        return path is null ? null : LoadFromAssemblyPath(path);
    }
}
