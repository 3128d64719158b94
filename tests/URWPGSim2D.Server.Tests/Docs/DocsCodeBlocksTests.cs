namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// Every C# example of README.md and docs/ is a sample that CI builds and runs: the block is
/// preceded by <c>&lt;!-- sample: samples/…/FILE.cs --&gt;</c> and is exactly the text between that
/// file's <c>// &lt;snippet&gt;</c> and <c>// &lt;/snippet&gt;</c> lines (each region de-indented,
/// regions joined by a blank line). Every sample with snippets is shown somewhere.
/// </summary>
public sealed class DocsCodeBlocksTests
{
    private static readonly string[] CSharp = ["csharp", "cs", "c#", "C#"];

    [Fact]
    public void EveryCSharpBlockIsExactlyItsSample()
    {
        var problems = new List<string>();
        foreach (var block in CSharpBlocks())
        {
            if (block.MarkerValue("sample") is not { } sample)
            {
                problems.Add($"{block.Where}: a C# block without a '<!-- sample: samples/.../File.cs -->' line before it");
                continue;
            }

            string path = Repository.PathOf(sample);
            if (!sample.StartsWith("samples/", StringComparison.Ordinal) || !File.Exists(path))
            {
                problems.Add($"{block.Where}: the sample {sample} does not exist under samples/");
                continue;
            }

            string snippet = Snippet(File.ReadAllLines(path));
            if (snippet != block.Text)
            {
                problems.Add($"{block.Where}: the block differs from the snippet of {sample}:\n--- block\n{block.Text}\n--- snippet\n{snippet}");
            }
        }

        Assert.True(problems.Count == 0, string.Join('\n', problems));
    }

    [Fact]
    public void EverySampleWithASnippetIsShownInTheDocs()
    {
        var shown = CSharpBlocks().Select(b => b.MarkerValue("sample")).OfType<string>().ToHashSet(StringComparer.Ordinal);
        var unshown = Directory.EnumerateFiles(Repository.PathOf("samples"), "*.cs", SearchOption.AllDirectories)
            .Where(f => !f.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", StringComparison.Ordinal)
                        && File.ReadLines(f).Any(l => l.Trim() == "// <snippet>"))
            .Select(f => Path.GetRelativePath(Repository.Root, f).Replace(Path.DirectorySeparatorChar, '/'))
            .Where(f => !shown.Contains(f))
            .ToList();

        Assert.True(unshown.Count == 0, "samples with a snippet no doc shows: " + string.Join(", ", unshown));
    }

    [Fact]
    public void TheSnippetReaderJoinsDeIndentedRegions()
    {
        string[] file =
        [
            "// header",
            "// <snippet>",
            "using A;",
            "// </snippet>",
            "class C {",
            "    void M() {",
            "        // <snippet>",
            "        var x = 1;",
            "",
            "        if (x > 0)",
            "            x++;",
            "        // </snippet>",
            "    }",
            "}",
        ];

        Assert.Equal("using A;\n\nvar x = 1;\n\nif (x > 0)\n    x++;", Snippet(file));
        Assert.Throws<InvalidDataException>(() => Snippet(["// <snippet>", "x"]));
        Assert.Throws<InvalidDataException>(() => Snippet(["x"]));
    }

    /// <summary>The snippet regions of a sample file, de-indented and joined by a blank line.</summary>
    internal static string Snippet(string[] lines)
    {
        var regions = new List<string>();
        for (int i = 0; i < lines.Length; i++)
        {
            if (lines[i].Trim() != "// <snippet>")
            {
                continue;
            }

            int indent = lines[i].Length - lines[i].TrimStart().Length;
            int end = Array.FindIndex(lines, i + 1, l => l.Trim() == "// </snippet>");
            if (end < 0)
            {
                throw new InvalidDataException($"line {i + 1}: a snippet is not closed");
            }

            regions.Add(string.Join('\n', lines[(i + 1)..end].Select(l => l.Length >= indent && l[..indent].Trim().Length == 0 ? l[indent..] : l.TrimStart())));
            i = end;
        }

        return regions.Count > 0 ? string.Join("\n\n", regions) : throw new InvalidDataException("no snippet in the file");
    }

    private static IEnumerable<MarkdownBlock> CSharpBlocks() =>
        Repository.MarkdownFiles().SelectMany(MarkdownBlock.Read).Where(b => CSharp.Contains(b.Info));
}
