using System.Reflection;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>
/// The assemblies of the original (and of XNA) whose types the compatibility assembly provides under
/// the same namespaces and names: a reference to any of them, whatever its version and public key token
/// (the original's are 1.2.123.20110 and <c>04f000b8db128100</c>, XNA's 3.1.0.0 and
/// <c>6d5c3888ef60e27d</c>), is retargeted to the compatibility assembly.
/// </summary>
public static class OriginalReferences
{
    private static readonly string[] Names =
        ["URWPGSim2D.Common", "URWPGSim2D.Core", "URWPGSim2D.StrategyLoader", "URWPGSim2D.StrategyHelper", "Microsoft.Xna.Framework"];

    /// <summary>The compatibility assembly, which every original reference becomes.</summary>
    public static AssemblyName Compat { get; } = typeof(OriginalReferences).Assembly.GetName();

    /// <summary>Whether <paramref name="name"/> is the simple name of one of the original's assemblies.</summary>
    /// <param name="name">Simple assembly name.</param>
    public static bool IsOriginal(string? name)
    {
        foreach (string n in Names)
        {
            if (string.Equals(n, name, StringComparison.OrdinalIgnoreCase))
            {
                return true;
            }
        }

        return false;
    }
}
