using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using Xunit;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// The Chinese strategies page keeps in step with the English one: its troubleshooting table has
/// the same rows (the same compiler error codes, or the same program message, row by row), and the
/// page names the same compiler codes as the English page.
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
