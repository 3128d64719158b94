namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>The clone the tests run in: its root (the folder of the .sln) and its Markdown files.</summary>
internal static class Repository
{
    private static readonly Lazy<string> RootFolder = new(() =>
    {
        for (var folder = new DirectoryInfo(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
        {
            if (File.Exists(Path.Combine(folder.FullName, "URWPGSim2D.Collision.sln")))
            {
                return folder.FullName;
            }
        }

        throw new InvalidOperationException($"no URWPGSim2D.Collision.sln above {AppContext.BaseDirectory}");
    });

    /// <summary>The repository's root folder.</summary>
    public static string Root => RootFolder.Value;

    /// <summary>A path relative to the root (forward slashes) made absolute.</summary>
    public static string PathOf(string relative) => Path.Combine(Root, relative.Replace('/', Path.DirectorySeparatorChar));

    /// <summary>README.md and its translations, every Markdown file under docs/, the package READMEs under src/ and the Python client's READMEs, as paths relative to the root.</summary>
    public static IReadOnlyList<string> MarkdownFiles() =>
        [
            "README.md",
            "README.zh-CN.md",
            .. Directory.EnumerateFiles(PathOf("docs"), "*.md", SearchOption.AllDirectories)
                .Select(f => Path.GetRelativePath(Root, f).Replace(Path.DirectorySeparatorChar, '/'))
                .Order(StringComparer.Ordinal),
            // The packed libraries' package READMEs (shown on the package's page).
            .. Directory.EnumerateFiles(PathOf("src"), "README.md", SearchOption.AllDirectories)
                .Select(f => Path.GetRelativePath(Root, f).Replace(Path.DirectorySeparatorChar, '/'))
                .Where(f => !f.Contains("/bin/", StringComparison.Ordinal) && !f.Contains("/obj/", StringComparison.Ordinal))
                .Order(StringComparer.Ordinal),
            // The Python client's README and its translation.
            "clients/python/README.md",
            "clients/python/README.zh-CN.md",
        ];

    /// <summary>The pages in Chinese: README.zh-CN.md, every Markdown file under docs/zh-CN/ and the Python client's README.zh-CN.md.</summary>
    public static IReadOnlyList<string> TranslatedPages() =>
        [
            "README.zh-CN.md",
            .. Directory.EnumerateFiles(PathOf("docs/zh-CN"), "*.md", SearchOption.AllDirectories)
                .Select(f => Path.GetRelativePath(Root, f).Replace(Path.DirectorySeparatorChar, '/'))
                .Order(StringComparer.Ordinal),
            "clients/python/README.zh-CN.md",
        ];

    /// <summary>The English page a Chinese page translates: docs/zh-CN/X.md is docs/X.md, any other X.zh-CN.md is X.md.</summary>
    public static string EnglishOf(string translated) =>
        translated.StartsWith("docs/zh-CN/", StringComparison.Ordinal)
            ? "docs/" + translated["docs/zh-CN/".Length..]
            : translated.Replace(".zh-CN.md", ".md", StringComparison.Ordinal);
}
