namespace URWPGSim2D.Hosting;

/// <summary>
/// The strategies a folder offers (<c>run --live --strategies DIR</c>): its <c>.cs</c> files and
/// <c>.dll</c> files, each sub-folder that holds <c>.cs</c> files (outside <c>bin</c> and <c>obj</c>, as
/// <c>--strategy TEAM=FOLDER</c> compiles them) and the <c>.dll</c> files directly in a sub-folder.
/// Each is named by its path relative to the folder, <c>/</c> between folders and after a folder of
/// sources: <c>teamA/</c>, <c>teamB.dll</c>, <c>teamC/TeamC.dll</c> (one level down only). Hidden
/// entries (a leading <c>.</c>) and the folders <c>bin</c> and <c>obj</c> are left out.
/// Nothing is loaded or compiled here; the folder is read again at every <see cref="Scan"/>, so a
/// strategy added while the server runs is offered at the next look.
/// </summary>
public static class StrategyCatalog
{
    /// <summary>The names of the strategies in <paramref name="folder"/>, sorted (ordinal); empty when it cannot be read.</summary>
    public static List<string> Scan(string folder)
    {
        var names = new List<string>();
        try
        {
            foreach (string file in Directory.EnumerateFiles(folder))
            {
                string name = Path.GetFileName(file);
                if (IsStrategyFile(name))
                {
                    names.Add(name);
                }
            }

            foreach (string dir in Directory.EnumerateDirectories(folder))
            {
                string name = Path.GetFileName(dir);
                if (name.StartsWith('.') || name is "bin" or "obj")
                {
                    continue;
                }

                if (HasSources(dir))
                {
                    names.Add(name + "/");
                }

                foreach (string file in Directory.EnumerateFiles(dir, "*.dll"))
                {
                    if (!Path.GetFileName(file).StartsWith('.'))
                    {
                        names.Add(name + "/" + Path.GetFileName(file));
                    }
                }
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // A folder that vanished or cannot be read offers what was found (the board says none).
        }

        names.Sort(StringComparer.Ordinal);
        return names;
    }

    /// <summary>The spec <c>--strategy</c> would take for <paramref name="name"/> of <see cref="Scan"/>.</summary>
    public static string Spec(string folder, string name) => Path.Combine(folder, name.TrimEnd('/').Replace('/', Path.DirectorySeparatorChar));

    private static bool IsStrategyFile(string name) => !name.StartsWith('.')
        && (name.EndsWith(".cs", StringComparison.OrdinalIgnoreCase) || name.EndsWith(".dll", StringComparison.OrdinalIgnoreCase));

    // Whether a folder holds sources; one the loader refuses (a symbolic link in it) is offered, to say why when chosen.
    private static bool HasSources(string dir)
    {
        try
        {
            return StrategyCompiler.SourceFiles(dir).Count > 0;
        }
        catch (StrategyLoadException)
        {
            return true;
        }
    }
}
