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

    [GeneratedRegex("`([^`]+)`", RegexOptions.CultureInvariant)]
    private static partial Regex CodeSpan();
}
