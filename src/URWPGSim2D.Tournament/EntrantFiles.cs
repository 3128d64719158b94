using System.Security.Cryptography;

namespace URWPGSim2D.Tournament;

/// <summary>
/// An entrant's files: the version of its code (a hash of its files, so that a tournament replays
/// the matches of an entrant whose code changed) and the entrants of a folder of entrants
/// (<c>tournament --entrants-dir DIR</c>).
/// </summary>
public static class EntrantFiles
{
    /// <summary>Hex digits of a version.</summary>
    public const int VersionLength = 12;

    /// <summary>
    /// The version of a SPEC's code: the first <see cref="VersionLength"/> hex digits of the SHA-256 of
    /// its files (a file: itself; a folder: every regular file under it, bin/ and obj/ at its top and
    /// hidden entries left out, by relative path in ordinal order, each path and content hashed); null
    /// for a built-in strategy or the demo.
    /// </summary>
    /// <param name="spec">The entrant's SPEC (a file or folder, optionally with <c>#Type</c>).</param>
    /// <exception cref="IOException">A file cannot be read.</exception>
    /// <exception cref="UnauthorizedAccessException">A file may not be read.</exception>
    public static string? Version(string spec)
    {
        string path = File.Exists(spec) || Directory.Exists(spec) || spec.LastIndexOf('#') <= 0 ? spec : spec[..spec.LastIndexOf('#')];
        using var sha = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        if (File.Exists(path))
        {
            sha.AppendData(File.ReadAllBytes(path));
        }
        else if (Directory.Exists(path))
        {
            var files = new List<string>();
            Collect(path, path, files);
            files.Sort(StringComparer.Ordinal);
            foreach (string relative in files)
            {
                sha.AppendData(Encoding.UTF8.GetBytes(relative.Replace('\\', '/') + "\n"));
                sha.AppendData(File.ReadAllBytes(Path.Combine(path, relative)));
            }
        }
        else
        {
            return null;
        }

        return Convert.ToHexStringLower(sha.GetHashAndReset())[..VersionLength];
    }

    /// <summary>
    /// The entrants of a folder: every sub-folder, <c>.cs</c> file and <c>.dll</c> file directly in it
    /// (hidden ones left out), named after it (a file without its extension), in ordinal order of the names.
    /// </summary>
    /// <param name="folder">The folder.</param>
    /// <returns>The entrants (name, SPEC) in name order.</returns>
    /// <exception cref="ArgumentException">Two entries give the same name (e.g. <c>a.cs</c> and <c>a/</c>): the message names both.</exception>
    public static List<Entrant> Of(string folder)
    {
        var byName = new SortedDictionary<string, string>(StringComparer.Ordinal);
        foreach (string entry in Directory.EnumerateFileSystemEntries(folder))
        {
            string file = Path.GetFileName(entry);
            if (file.StartsWith('.'))
            {
                continue;
            }

            string? name = Directory.Exists(entry) ? file
                : file.EndsWith(".cs", StringComparison.OrdinalIgnoreCase) || file.EndsWith(".dll", StringComparison.OrdinalIgnoreCase) ? Path.GetFileNameWithoutExtension(file)
                : null;
            if (name is null || name.Length == 0)
            {
                continue;
            }

            if (byName.TryGetValue(name, out string? other))
            {
                throw new ArgumentException($"{Path.GetFileName(other)} and {file} both make the entrant {name}; rename one");
            }

            byName[name] = entry;
        }

        var entrants = new List<Entrant>(byName.Count);
        foreach (var (name, spec) in byName)
        {
            entrants.Add(new Entrant(name, spec));
        }

        return entrants;
    }

    private static void Collect(string root, string folder, List<string> files)
    {
        foreach (string entry in Directory.EnumerateFileSystemEntries(folder))
        {
            string relative = Path.GetRelativePath(root, entry);
            var info = new FileInfo(entry);
            if (Path.GetFileName(entry).StartsWith('.') || relative is "bin" or "obj" || info.LinkTarget is not null)
            {
                continue;
            }

            if (info.Attributes.HasFlag(FileAttributes.Directory))
            {
                Collect(root, entry, files);
            }
            else
            {
                files.Add(relative);
            }
        }
    }
}
