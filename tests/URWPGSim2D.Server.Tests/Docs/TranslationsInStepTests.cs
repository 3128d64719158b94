using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// The Chinese strategies page keeps in step with the English one: its troubleshooting table has
/// the same rows (the same compiler error codes, or the same program message, row by row), and the
/// page names the same compiler codes as the English page. Every Chinese page's copies of outputs
/// checked on its English page are the English page's outputs.
/// </summary>
public sealed partial class TranslationsInStepTests
{
    private const string English = "docs/strategies.md";
    private const string Chinese = "docs/zh-CN/strategies.md";

    [Fact]
    public void TheTroubleshootingTablesHaveTheSameRows()
    {
        var english = TableRows(English, "## Troubleshooting compile errors");
        var chinese = TableRows(Chinese, "## 编译错误排查");

        Assert.True(english.Count >= 5, "the English troubleshooting table has its rows");
        Assert.True(
            english.SequenceEqual(chinese, StringComparer.Ordinal),
            $"the troubleshooting rows differ (first column's codes, row by row):\n{English}: {string.Join(" | ", english)}\n{Chinese}: {string.Join(" | ", chinese)}");
    }

    [Fact]
    public void ThePagesNameTheSameCompilerCodes()
    {
        var english = Codes(File.ReadAllText(Repository.PathOf(English)));
        var chinese = Codes(File.ReadAllText(Repository.PathOf(Chinese)));
        Assert.True(
            english.SetEquals(chinese),
            $"only in {English}: {string.Join(", ", english.Except(chinese))}; only in {Chinese}: {string.Join(", ", chinese.Except(english))}");
    }

    /// <summary>
    /// A Chinese page shows the outputs its English page shows: a block the docs test does not run
    /// (marked <c>&lt;!-- output: not run (…) --&gt;</c> or <c>&lt;!-- .ci/… --&gt;</c>, checked on the
    /// English page by the test or CI script the marker names) is a copy of the English page's block
    /// with the same marker, timing figures aside, so a regenerated English output makes its copy fail
    /// here until it is copied again.
    /// </summary>
    [Fact]
    public void TheChinesePagesCopiesOfCheckedOutputsAreTheEnglishPagesOutputs()
    {
        var problems = new List<string>();
        int copies = 0;
        foreach (string page in Repository.TranslatedPages().Where(p => p != "README.zh-CN.md"))
        {
            string englishPage = Repository.EnglishOf(page);
            if (!File.Exists(Repository.PathOf(englishPage)))
            {
                problems.Add($"{page}: no English page {englishPage}");
                continue;
            }

            var english = MarkdownBlock.Read(englishPage).Where(b => b.Marker is not null).ToList();
            foreach (var block in MarkdownBlock.Read(page).Where(b => !DocsOutputsTests.RunsForReal(b) && b.Text.StartsWith("$ ", StringComparison.Ordinal)))
            {
                copies++;
                if (block.Marker is null)
                {
                    problems.Add($"{block.Where}: a transcript that is not run, without the marker of the English block it copies");
                }
                else if (!english.Any(e => e.Marker == block.Marker && Transcript.Matches(e.Text, block.Text)))
                {
                    problems.Add($"{block.Where}: no block of {englishPage} marked \"<!-- {block.Marker} -->\" shows this output; copy the English block again");
                }
            }
        }

        Assert.True(copies > 0, "the Chinese pages show copies of checked outputs");
        Assert.True(problems.Count == 0, string.Join('\n', problems));
    }

    /// <summary>
    /// Every page README.md lists for strategy writers has a Chinese page, and README.zh-CN.md links
    /// every Chinese page.
    /// </summary>
    [Fact]
    public void EveryPageForStrategyWritersIsInChineseAndTheChineseReadmeLinksEveryChinesePage()
    {
        string[] readme = File.ReadAllLines(Repository.PathOf("README.md"));
        int from = Array.IndexOf(readme, "For strategy writers:");
        int to = Array.IndexOf(readme, "For users of the server:");
        Assert.True(from >= 0 && to > from, "README.md lists the pages for strategy writers");
        var pages = readme[from..to]
            .Select(l => ListedPage().Match(l))
            .Where(m => m.Success)
            .Select(m => m.Groups[1].Value)
            .ToList();
        Assert.Contains("docs/learning.md", pages);

        var missing = pages
            .Select(p => p.StartsWith("docs/", StringComparison.Ordinal) ? "docs/zh-CN/" + p["docs/".Length..] : p.Replace(".md", ".zh-CN.md", StringComparison.Ordinal))
            .Where(p => !File.Exists(Repository.PathOf(p)))
            .ToList();
        Assert.True(missing.Count == 0, "no Chinese page: " + string.Join(", ", missing));

        string chineseReadme = File.ReadAllText(Repository.PathOf("README.zh-CN.md"));
        var unlinked = Repository.TranslatedPages()
            .Where(p => p != "README.zh-CN.md" && !chineseReadme.Contains("](" + p + ")", StringComparison.Ordinal))
            .ToList();
        Assert.True(unlinked.Count == 0, "README.zh-CN.md does not link: " + string.Join(", ", unlinked));
    }

    [Fact]
    public void TheRowReaderKeysARowByItsCodesOrItsMessage()
    {
        Assert.Equal("CS0246 CS0234", RowKey("| `CS0246`/`CS0234` 找不到类型（`Form`） | 删掉 |"));
        Assert.Equal("… has no public strategy class", RowKey("| `… has no public strategy class` (exit 2) | the class |"));
        Assert.Equal(["CS0101", "SYSLIB0010"], Codes("CS0101 在中文里CS0101，SYSLIB0010; CS12345 is not one").Order());
    }

    /// <summary>The key of each row of the first table after a heading.</summary>
    private static List<string> TableRows(string file, string heading)
    {
        string[] lines = File.ReadAllLines(Repository.PathOf(file));
        int at = Array.IndexOf(lines, heading);
        Assert.True(at >= 0, $"{file} has no heading \"{heading}\"");
        var rows = lines.Skip(at + 1)
            .SkipWhile(l => !l.StartsWith('|'))
            .TakeWhile(l => l.StartsWith('|'))
            .Skip(2) // the header and the |---| line
            .Select(RowKey)
            .ToList();
        return rows;
    }

    /// <summary>A row's compiler codes in its first column, or (none) the first code span there.</summary>
    private static string RowKey(string row)
    {
        string first = row.Split('|', StringSplitOptions.RemoveEmptyEntries)[0];
        var codes = CodeWord().Matches(first).Select(m => m.Value).ToList();
        if (codes.Count > 0)
        {
            return string.Join(' ', codes);
        }

        Match span = CodeSpan().Match(first);
        return span.Success ? span.Groups[1].Value : first.Trim();
    }

    private static HashSet<string> Codes(string text) => [.. CodeWord().Matches(text).Select(m => m.Value)];

    // A compiler code as a word of its own, also between Chinese characters (which \b treats as letters).
    [GeneratedRegex(@"(?<![A-Za-z0-9])(CS|SYSLIB)[0-9]{4}(?![0-9])", RegexOptions.CultureInvariant)]
    private static partial Regex CodeWord();

    // A list item of README.md's documentation section: "- [docs/x.md](docs/x.md): …".
    [GeneratedRegex(@"^- \[[^\]]+\]\(([^)#]+)\)", RegexOptions.CultureInvariant)]
    private static partial Regex ListedPage();

    [GeneratedRegex("`([^`]+)`", RegexOptions.CultureInvariant)]
    private static partial Regex CodeSpan();
}
