using static URWPGSim2D.Server.Viewer.Tests.PageProbe;

namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>
/// Strategy drawings in the replay page (<c>run --debug-draw --html</c>): chase-ball's plan appears
/// where the trace says it drew it, a team's layer can be turned off, and the page stays quiet and offline.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed class DebugDrawPageTests(Browser browser, RecordedMatch match)
{
    private static readonly (int R, int G, int B) Aim = (0xff, 0xd4, 0x00);

    private (string Html, JsonElement[] Lines) Record(int cycles)
    {
        string html = Path.Combine(match.Folder, $"draw-{cycles}.html"), trace = Path.Combine(match.Folder, $"draw-{cycles}.jsonl");
        var run = RecordedMatch.Cli("run", "--item", "default", "--cycles", cycles.ToString(System.Globalization.CultureInfo.InvariantCulture), "--debug-draw", "--trace", trace, "--html", html);
        Assert.True(run.Code == 0, run.Stderr);
        return (html, File.ReadLines(trace).Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray());
    }

    // The aim points (chase-ball's yellow dots) of a team in a trace line.
    private static Vector2[] AimPoints(JsonElement line, int team) =>
        line.GetProperty("draw").EnumerateArray()
            .Where(d => d.GetProperty("team").GetInt32() == team && d.GetProperty("kind").GetString() == "point")
            .Select(d => Point(d.GetProperty("at"))).ToArray();

    [Fact]
    public async Task The_plan_is_drawn_where_the_strategy_put_it_and_each_team_layer_turns_off()
    {
        var (html, lines) = Record(300);
        var (page, errors, requests) = await OpenFile(browser, html);
        await page.ClickAsync("#show-labels"); // ids off: nothing on top of the drawings
        Assert.True(await page.IsVisibleAsync("#show-draw0"));
        Assert.True(await page.IsVisibleAsync("#show-draw1"));
        int matched = 0, total = 0;
        foreach (int cycle in (int[])[1, 100, 217, 300])
        {
            await Scrub(page, cycle);
            int shown = await page.EvaluateAsync<int>("k => urwpg.drawingsAt(k).length", cycle);
            Assert.Equal(lines[cycle].GetProperty("draw").GetArrayLength(), shown);
            foreach (int team in (int[])[0, 1])
            {
                var points = AimPoints(lines[cycle], team);
                Assert.NotEmpty(points);
                var rgb = await Pixels(page, points);
                total += rgb.Length;
                matched += rgb.Count(c => Near(c, Aim));
            }
        }

        // Another shape drawn later may cover a dot now and then; most must show.
        Assert.True(matched >= total * 4 / 5, $"{matched} of {total} aim points show the aim colour");

        // Team 0's layer off: its dots are gone, team 1's stay.
        await Scrub(page, 100);
        await page.ClickAsync("#show-draw0");
        await Settle(page);
        var off = await Pixels(page, AimPoints(lines[100], 0));
        Assert.DoesNotContain(off, c => Near(c, Aim));
        var on = await Pixels(page, AimPoints(lines[100], 1));
        Assert.Contains(on, c => Near(c, Aim));

        lock (requests)
        {
            Assert.Equal([new Uri(html).AbsoluteUri], requests.Where(u => !u.StartsWith("data:", StringComparison.Ordinal)).ToArray());
        }

        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task A_page_without_drawings_has_no_drawing_layers()
    {
        var (page, errors, _) = await OpenFile(browser, match.HtmlPath);
        Assert.False(await page.IsVisibleAsync("#draw-layers"));
        Assert.Equal(0, await page.EvaluateAsync<int>("() => urwpg.drawingsAt(100).length"));
        Assert.DoesNotContain("\"draws\"", File.ReadAllText(match.HtmlPath), StringComparison.Ordinal);
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task ScreenshotOfTheDrawings()
    {
        var (html, _) = Record(120);
        var (page, errors, _) = await OpenFile(browser, html);
        await page.SelectOptionAsync("#follow", "0");
        await page.Keyboard.PressAsync("End");
        await Settle(page);
        Assert.Equal("cycle 120 / 120", await page.TextContentAsync("#cycle"));
        await Figures.Shoot(page, "debug-draw.png", match.Folder);
        NoErrors(errors);
        await page.Context.CloseAsync();
    }
}
