using static URWPGSim2D.Server.Viewer.Tests.PageProbe;

namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>What a strategy printed (<c>run --strategy-log --html</c>), listed beside the events up to the cycle shown and filtered by team.</summary>
[Collection(BrowserCollection.Name)]
public sealed class StrategyOutputPageTests(Browser browser, RecordedMatch match)
{
    private sealed record Entry(int Cycle, int Team, string Text);

    private static async Task<Entry[]> Shown(Microsoft.Playwright.IPage page) =>
        JsonSerializer.Deserialize<Entry[]>(await page.EvaluateAsync<string>("() => JSON.stringify(urwpg.logsShown())"), new JsonSerializerOptions(JsonSerializerDefaults.Web))!;

    [Fact]
    public async Task The_output_of_each_team_is_listed_up_to_the_cycle_shown_and_filters_by_team()
    {
        string html = Path.Combine(match.Folder, "log.html"), trace = Path.Combine(match.Folder, "log.jsonl");
        string source = SdkStrategy.Write(match.Folder, "Printer", "printer", """
            Console.WriteLine($"saw cycle {s.Cycle}, {fish.Length} fish");
            d.Fill(new Decision(4, 7));
            """);
        var run = RecordedMatch.Cli("run", "--item", "default", "--cycles", "40", "--strategy", "0=" + source, "--strategy", "1=" + source,
            "--strategy-timeout", "5000", "--strategy-log", "--trace", trace, "--html", html);
        Assert.True(run.Code == 0, run.Stderr);
        var expected = File.ReadLines(trace).Select(l => JsonDocument.Parse(l).RootElement)
            .SelectMany(l => l.TryGetProperty("log", out var log)
                ? log.EnumerateArray().Select(e => new Entry(l.GetProperty("cycle").GetInt32(), e.GetProperty("team").GetInt32(), e.GetProperty("text").GetString()!))
                : [])
            .ToArray();
        Assert.Equal(80, expected.Length);

        var (page, errors, _) = await OpenFile(browser, html);
        Assert.True(await page.IsVisibleAsync("#strategy-output"));
        await Scrub(page, 25);
        var shown = await Shown(page);
        Assert.Equal(expected.Where(e => e.Cycle <= 25).Reverse(), shown);
        Assert.Equal("saw cycle 24, 2 fish\n", shown[0].Text);

        await page.SelectOptionAsync("#log-team", "1");
        await Settle(page);
        shown = await Shown(page);
        Assert.Equal(expected.Where(e => e.Cycle <= 25 && e.Team == 1).Reverse(), shown);

        // A click on an entry jumps to its cycle.
        await page.ClickAsync("#strategy-log li:nth-child(5)");
        await Settle(page);
        Assert.Equal(shown[4].Cycle, await Cycle(page));
        await page.SelectOptionAsync("#log-team", "all");
        await Settle(page);
        await Figures.Shoot(page, "strategy-output.png", match.Folder);
        NoErrors(errors);
        await page.Context.CloseAsync();
    }
}
