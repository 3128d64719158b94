namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Disjoint sets over indices in a parent array (an index that is its own parent is a root; the
/// root of a set is always its smallest index, so the sets come out the same whatever order the
/// unions were made in). Roots are found with path halving.
/// </summary>
internal static class DisjointSets
{
    /// <summary>The root (smallest index) of the set holding <paramref name="i"/>.</summary>
    public static int Root(Span<int> parent, int i)
    {
        while (parent[i] != i)
        {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }

        return i;
    }

    /// <summary>Joins the sets of <paramref name="a"/> and <paramref name="b"/> under the smaller root.</summary>
    public static void Union(Span<int> parent, int a, int b)
    {
        int ra = Root(parent, a), rb = Root(parent, b);
        if (ra != rb)
        {
            parent[Math.Max(ra, rb)] = Math.Min(ra, rb);
        }
    }
}
