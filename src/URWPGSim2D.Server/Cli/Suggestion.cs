namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The known name nearest to a mistyped one, for "did you mean" hints: the one a few edits away
/// (insertions, deletions, substitutions and swaps of neighbours, without regard to case), or the
/// only one the typed name begins.
/// </summary>
internal static class Suggestion
{
    /// <summary>The nearest of <paramref name="known"/> to <paramref name="given"/>, or null when none is near.</summary>
    /// <param name="given">The mistyped name.</param>
    /// <param name="known">The names.</param>
    /// <returns>At most one edit away for a name of up to 7 letters (dashes aside), at most two for a longer one; the first of equals; else the only name <paramref name="given"/> begins; else null.</returns>
    public static string? Nearest(string given, IEnumerable<string> known)
    {
        ArgumentNullException.ThrowIfNull(given);
        ArgumentNullException.ThrowIfNull(known);
        int letters = given.TrimStart('-').Length;
        int allowed = letters >= 8 ? 2 : 1;
        string? best = null;
        int bestDistance = int.MaxValue;
        string? prefixOf = null;
        int prefixes = 0;
        foreach (string name in known)
        {
            if (string.Equals(name, given, StringComparison.Ordinal))
            {
                continue;
            }

            int d = Distance(given, name);
            if (d <= allowed && d < bestDistance)
            {
                (best, bestDistance) = (name, d);
            }

            if (letters >= 3 && name.StartsWith(given, StringComparison.OrdinalIgnoreCase))
            {
                prefixOf = name;
                prefixes++;
            }
        }

        return best ?? (prefixes == 1 ? prefixOf : null);
    }

    /// <summary>Edits from <paramref name="a"/> to <paramref name="b"/> (optimal string alignment, case-insensitive).</summary>
    public static int Distance(string a, string b)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);
        var d = new int[a.Length + 1, b.Length + 1];
        for (int i = 0; i <= a.Length; i++)
        {
            d[i, 0] = i;
        }

        for (int j = 0; j <= b.Length; j++)
        {
            d[0, j] = j;
        }

        for (int i = 1; i <= a.Length; i++)
        {
            for (int j = 1; j <= b.Length; j++)
            {
                int cost = char.ToUpperInvariant(a[i - 1]) == char.ToUpperInvariant(b[j - 1]) ? 0 : 1;
                int v = Math.Min(Math.Min(d[i - 1, j] + 1, d[i, j - 1] + 1), d[i - 1, j - 1] + cost);
                if (i > 1 && j > 1 && char.ToUpperInvariant(a[i - 1]) == char.ToUpperInvariant(b[j - 2]) && char.ToUpperInvariant(a[i - 2]) == char.ToUpperInvariant(b[j - 1]))
                {
                    v = Math.Min(v, d[i - 2, j - 2] + 1);
                }

                d[i, j] = v;
            }
        }

        return d[a.Length, b.Length];
    }
}
