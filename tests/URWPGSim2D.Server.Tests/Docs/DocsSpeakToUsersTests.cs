using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// README and docs/ speak to users about the product as it is: no page tells how it was built
/// (the history is in git), and the performance page stays a short page of figures, without goals;
/// how to rerun the benchmarks is on the contributors' page.
/// </summary>
public sealed partial class DocsSpeakToUsersTests
{
    [Fact]
    public void NoPageSpeaksOfIssuesOrSessions()
    {
        var found = new List<string>();
        foreach (string file in Repository.MarkdownFiles())
        {
            string[] lines = File.ReadAllLines(Repository.PathOf(file));
            for (int i = 0; i < lines.Length; i++)
            {
                if (History().IsMatch(lines[i]))
                {
                    found.Add($"{file}:{i + 1}: {lines[i].Trim()}");
                }
            }
        }

        Assert.True(found.Count == 0, "pages that speak of issues or sessions:\n" + string.Join('\n', found));
    }

    [Theory]
    [InlineData("the issue's goals", true)]
    [InlineData("Issue 10, third session", true)]
    [InlineData("other sessions building", true)]
    [InlineData("a tissue of lies; reissued", false)]
    [InlineData("the session-less protocol", true)]
    public void TheCheckFindsTheWords(string line, bool found) => Assert.Equal(found, History().IsMatch(line));

    [Fact]
    public void ThePerformancePageIsShortAndKeepsItsFigures()
    {
        string page = File.ReadAllText(Repository.PathOf("docs/performance.md"));
        Assert.True(page.Split('\n').Length < 250, "docs/performance.md is a short page");
        Assert.Contains("![cost per cycle against object count](figures/scaling.svg)", page, System.StringComparison.Ordinal);
        Assert.Contains("| distance, polygon–polygon | 272 ns | 144 ns | 0.53 |", page, System.StringComparison.Ordinal);
        Assert.DoesNotContain("met?", page, System.StringComparison.Ordinal);
        Assert.DoesNotContain("**no**", page, System.StringComparison.Ordinal);
        Assert.Contains("development.md#benchmarks", page, System.StringComparison.Ordinal);
        Assert.Contains("bash benchmarks/run-all.sh", File.ReadAllText(Repository.PathOf("docs/development.md")), System.StringComparison.Ordinal);
    }

    [GeneratedRegex(@"\b(issues?|sessions?)\b", RegexOptions.IgnoreCase | RegexOptions.CultureInvariant)]
    private static partial Regex History();
}
