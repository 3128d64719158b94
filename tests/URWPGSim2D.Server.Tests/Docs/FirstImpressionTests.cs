using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// The first matches a reader plays show a real match: the README's first command (the install
/// block's) and its first ball-grab transcript, in English and Chinese, end with goals, and the
/// ball-grab rule that a team scores in the box at its own end is on the Chinese items page too.
/// </summary>
public sealed partial class FirstImpressionTests
{
    [Theory]
    [InlineData("README.md")]
    [InlineData("README.zh-CN.md")]
    public void The_first_command_of_the_readme_plays_a_match_with_goals(string file)
    {
        var block = MarkdownBlock.Read(file).First(b => b.Text.Contains("dotnet run -c Release --project src/URWPGSim2D.Server", StringComparison.Ordinal));
        string line = block.Text.Split('\n').First(l => l.StartsWith("dotnet run -c Release --project src/URWPGSim2D.Server", StringComparison.Ordinal));
        string[] args = line.Contains(" -- ", StringComparison.Ordinal) ? line[(line.IndexOf(" -- ", StringComparison.Ordinal) + 4)..].Split(' ', StringSplitOptions.RemoveEmptyEntries) : [];
        var (code, stdout, stderr) = DocsOutputsTests.RunServer(string.Empty, args);
        Assert.True(code == 0, stderr);
        AssertGoals(stdout, $"{file}: `{line}`");
    }

    [Theory]
    [InlineData("README.md", "$ urwpgsim2d run --item ball-grab")]
    [InlineData("README.zh-CN.md", "$ urwpgsim2d run --item 抢球博弈")]
    public void The_readmes_first_ball_grab_match_shows_goals(string file, string command)
    {
        var block = MarkdownBlock.Read(file).First(b => b.Text.StartsWith(command, StringComparison.Ordinal));
        AssertGoals(block.Text, $"{file}: {block.Text.Split('\n')[0]}"); // DocsOutputsTests checks that this is what the command prints
    }

    [Fact]
    public void The_chinese_items_page_says_a_team_scores_in_the_box_at_its_own_end()
    {
        string page = System.IO.File.ReadAllText(Repository.PathOf("docs/zh-CN/items.md"));
        string section = page[page.IndexOf("## 抢球博弈 ball-grab", StringComparison.Ordinal)..];
        Assert.Contains("完整进入**某队自己这一端**的球框时，该队得到这个球的分值", section, StringComparison.Ordinal);
        Assert.Contains("[docs/zh-CN/items.md](docs/zh-CN/items.md)", System.IO.File.ReadAllText(Repository.PathOf("README.zh-CN.md")), StringComparison.Ordinal);
    }

    private static void AssertGoals(string output, string what)
    {
        var score = ScoreLine().Match(output);
        Assert.True(score.Success, $"{what}: no score line in\n{output}");
        Assert.True(int.Parse(score.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) + int.Parse(score.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture) > 0,
            $"{what} ends {score.Groups[1].Value}:{score.Groups[2].Value}: a first match should show goals");
    }

    [GeneratedRegex(@"^score: team 0 \(.*\) (\d+), team 1 \(.*\) (\d+)$", RegexOptions.Multiline)]
    private static partial Regex ScoreLine();
}
